#pragma once
// The flags of `hemiroll screenshot`, parsed and checked before any file is read.

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/render/RenderScene.h"

namespace hemiroll::game {

struct ScreenshotOptions {
  std::string levelPath;
  std::string outPath;                                    // --out (required)
  std::vector<std::pair<int, double>> state;              // --state name=value,...: (slot, value)
  render::CameraMode camera = render::CameraMode::Follow; // --camera
  double zoom = 1.0;                                      // --zoom
  int width = 1280, height = 720;                         // --size WxH
  std::optional<std::array<double, 3>> proxy;             // --proxy x,y,z [m]
  int frames = 0;                                         // --frames N: time N frames, print the median fps
  bool help = false;
};

struct ScreenshotOptionsResult {
  ScreenshotOptions options;
  std::string error;  // empty when the flags are good
};

// Parses the arguments after "screenshot". Accepts "--flag value" and "--flag=value".
ScreenshotOptionsResult parseScreenshotOptions(const std::vector<std::string>& args);

const char* screenshotUsage();

}  // namespace hemiroll::game
