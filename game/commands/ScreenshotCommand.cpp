#include "game/commands/ScreenshotCommand.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "engine/physics/ForceCoupling.h"
#include "engine/physics/Orientation.h"
#include "engine/physics/StateKinematics.h"
#include "engine/platform/PlatformError.h"
#include "engine/platform/Window.h"
#include "engine/render/Framebuffer.h"
#include "engine/render/RenderError.h"
#include "engine/render/Renderer.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/ScriptError.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/commands/ScreenshotOptions.h"
#include "game/ui/view/ShippedDirectories.h"
#include "game/ui/view/RenderSceneBuilder.h"

namespace hemiroll::game {

namespace {

constexpr const char* kPrefix = "hemiroll screenshot: ";

// The proxy, the spring and the level's coupling force for a proxy held at
// rest at `proxy` (the hand force of ForceCoupling with zero relative velocity).
void addProxy(const task::LevelDef& level, const physics::ForceDrivenState& x, const std::array<double, 3>& proxy,
              render::RenderScene& scene) {
  namespace slot = physics::force_slot;
  const physics::Vec3 p = physics::massPointPosition(x, level.params.radius);
  const physics::Orientation o = physics::makeOrientation(x[slot::u_o], x[slot::v_o], x[slot::psi]);
  const physics::Real3 dr{p[0] - proxy[0], p[1] - proxy[1], p[2] - proxy[2]};
  const physics::Real3 f = physics::handForce(level.coupling, physics::Real3::from(o.faceNormal()), dr, {0, 0, 0});
  scene.showProxy = true;
  scene.springOn = true;
  scene.proxyPosition = proxy;
  scene.force = {f.x, f.y, f.z};
}

// Renders `frames` frames and returns the median frames per second (each
// frame waits for the GPU, so the time is the frame's, not the queue's).
double timeFrames(render::Renderer& renderer, const render::RenderScene& scene, int width, int height, int frames) {
  std::vector<double> seconds;
  seconds.reserve(std::size_t(frames));
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(scene, width, height);
    glFinish();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(seconds.begin(), seconds.begin() + frames / 2, seconds.end());
  return 1.0 / seconds[std::size_t(frames / 2)];
}

}  // namespace

int runScreenshotCommand(const std::vector<std::string>& args) {
  const ScreenshotOptionsResult parsed = parseScreenshotOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning(kPrefix, parsed, screenshotUsage())) return *exit;
  const ScreenshotOptions& o = parsed.options;

  script::LoadedLevel level;
  try {
    level = script::LevelLoader().loadFile(o.levelPath);
  } catch (const std::exception& e) {
    std::cerr << kPrefix << e.what() << "\n";
    return kExitUsage;
  }
  physics::ForceDrivenState state = level.def.initial;
  for (const auto& [slot, value] : o.state) state[slot] = value;

  render::RenderScene scene;
  fillFromState(level.def, state, 0, scene);
  scene.camera.mode = o.camera;
  scene.camera.zoom = o.zoom;
  if (o.proxy) addProxy(level.def, state, *o.proxy, scene);

  try {
    platform::WindowDef windowDef;
    windowDef.title = "hemiroll screenshot";
    windowDef.width = 64;
    windowDef.height = 64;
    windowDef.hidden = true;
    windowDef.vsync = false;
    auto window = platform::Window::create(windowDef);
    render::RendererDef rendererDef;
    rendererDef.assetsDir = findAssetsDirectory();
    if (rendererDef.assetsDir.empty()) rendererDef.assetsDir = "assets";
    render::Renderer renderer(rendererDef);
    for (const std::string& note : renderer.notes()) std::cerr << kPrefix << "note: " << note << "\n";
    for (const std::string& note : renderer.setProps(propsOf(level.def))) std::cerr << kPrefix << "note: " << note << "\n";
    render::Framebuffer target(o.width, o.height);
    target.bind();
    renderer.render(scene, o.width, o.height);
    render::writePng(o.outPath, target.read());
    std::cout << kPrefix << o.outPath << " (" << o.width << "x" << o.height << ", " << window->glRenderer() << ")\n";
    if (o.frames > 0) {
      const double fps = timeFrames(renderer, scene, o.width, o.height, o.frames);
      std::printf("%smedian %.1f frames per second over %d frames at %dx%d\n", kPrefix, fps, o.frames, o.width,
                  o.height);
    }
  } catch (const platform::PlatformError& e) {
    std::cerr << kPrefix << e.what() << "\n";
    return kExitFailure;
  } catch (const render::RenderError& e) {
    std::cerr << kPrefix << e.what() << "\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace hemiroll::game
