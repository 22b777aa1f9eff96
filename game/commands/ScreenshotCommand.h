#pragma once
// `hemiroll screenshot`: one frame of a level, rendered offscreen, as a PNG
// (docs/RENDERING.md). Exit codes as every command (ExitCode.h).

#include <string>
#include <vector>

namespace hemiroll::game {

int runScreenshotCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
