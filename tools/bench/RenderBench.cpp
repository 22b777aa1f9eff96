// Frames per second of the renderer (engine/render) for a typical play
// scene at 1280x720: the hemisphere tilted and turned, proxy, spring, force
// arrow, target band, forbidden zone and a full contact trace (4096 points).
// Needs a display: tools/run-benchmarks.sh runs it under xvfb-run with
// LIBGL_ALWAYS_SOFTWARE=1 (Mesa's llvmpipe). Two variants:
//   Offscreen: into a Framebuffer, glFinish per frame (the renderer's cost);
//   Window:    into a visible window, SwapWindow per frame, vsync off (what
//              the game pays, including the copy to the X server);
//   WindowWithServo: the same while a ServoLoop holds 1 kHz on its own
//              thread (a scripted hand circling); each frame takes the
//              latest snapshot's pose. Counters: the loop's tick rate and
//              lateness over the run (issue 6: >= 60 fps with 1 kHz held).
// Real time and process CPU time (llvmpipe's own threads included) per frame;
// frames per second = 1 / the real time's median.
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "engine/haptics/devices/ScriptedDevice.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/physics/Orientation.h"
#include "engine/platform/PlatformError.h"
#include "engine/platform/Window.h"
#include "engine/render/ContactTrace.h"
#include "engine/render/Framebuffer.h"
#include "engine/render/Renderer.h"

namespace {

using namespace hemiroll;

constexpr int kW = 1280, kH = 720;

render::RenderScene typicalScene(const render::ContactTrace& trace) {
  render::RenderScene s;
  s.radius = 0.04;
  s.centre = {-0.012, -0.018, 0.04};
  const physics::Orientation o = physics::makeOrientation(0.25, -0.15, 2.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s.orientation[3 * i + j] = o.R(i, j);
  s.massPoint = {0.012, -0.006};
  s.showProxy = true;
  s.proxyPosition = {0.0, -0.02, 0.05};
  s.springOn = true;
  s.force = {0.8, -0.4, 1.5};
  s.targets.push_back({{-0.04, -0.04}, {0.004, 0.004}, false});
  s.forbidden.push_back({true, {0.05, 0.03}, 0.015, {}, {}});
  s.trace = &trace;
  s.time = 60.0;
  return s;
}

void fillTrace(render::ContactTrace& trace) {
  // The paper's helix seen on the plane: loops drifting towards the target.
  for (int i = 0; trace.size() < trace.capacity(); ++i) {
    const double t = 0.015 * i;
    trace.push(-0.012 * t / 60.0 * 3 + 0.01 * std::cos(t), -0.018 * t / 60.0 * 3 + 0.01 * std::sin(t), t);
  }
}

struct Fixture {
  std::unique_ptr<platform::Window> window;
  std::unique_ptr<render::Renderer> renderer;
  render::ContactTrace trace;
  render::RenderScene scene;
  bool ok = false;
};

Fixture& fixture() {
  static Fixture f;
  if (f.window) return f;
  try {
    f.window = platform::Window::create({.title = "hemiroll render_bench", .width = kW, .height = kH, .vsync = false});
    render::RendererDef def;
    def.assetsDir = HEMIROLL_SOURCE_DIR "/assets";
    f.renderer = std::make_unique<render::Renderer>(def);
    fillTrace(f.trace);
    f.scene = typicalScene(f.trace);
    f.ok = true;
    std::fprintf(stderr, "render_bench: %s\n", f.window->glRenderer().c_str());
  } catch (const platform::PlatformError& e) {
    std::fprintf(stderr, "render_bench: %s\n", e.what());
  }
  return f;
}

void BM_RenderFrameOffscreen(benchmark::State& state) {
  Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("no display (run under xvfb-run -a)");
  render::Framebuffer target(kW, kH);
  target.bind();
  render::RenderScene scene = f.scene;
  if (state.range(0) == 0) scene.trace = nullptr;
  for (auto _ : state) {
    f.renderer->render(scene, kW, kH);
    glFinish();
  }
  render::Framebuffer::bindDefault();
}
// Argument: with (1) or without (0) the 4096-point trace.
BENCHMARK(BM_RenderFrameOffscreen)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();

void BM_RenderFrameWindow(benchmark::State& state) {
  Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("no display (run under xvfb-run -a)");
  render::Framebuffer::bindDefault();
  const platform::PixelSize size = f.window->drawableSize();
  for (auto _ : state) {
    f.renderer->render(f.scene, size.width, size.height);
    f.window->swap();
    glFinish();
  }
}
BENCHMARK(BM_RenderFrameWindow)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();

haptics::DeviceReading circlingHand(double t) {
  constexpr double r = 0.005, w = 2.0 * M_PI;  // 5 mm circles at 1 Hz, 4 cm up
  haptics::DeviceReading d;
  d.position = haptics::Vec3(r * std::sin(w * t), r * (1.0 - std::cos(w * t)), 0.04);
  d.velocity = haptics::Vec3(r * w * std::cos(w * t), r * w * std::sin(w * t), 0.0);
  return d;
}

void BM_RenderFrameWindowWithServo(benchmark::State& state) {
  Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("no display (run under xvfb-run -a)");
  haptics::ScriptedDevice device(circlingHand);
  haptics::ServoLoop loop(haptics::ServoLoopDef{}, device);
  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);
  loop.start();
  render::Framebuffer::bindDefault();
  const platform::PixelSize size = f.window->drawableSize();
  render::RenderScene scene = f.scene;
  haptics::ServoSnapshot snap;
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t ticks0 = loop.ticks();
  for (auto _ : state) {
    if (loop.latest(snap)) {
      const auto& x = snap.state;
      const physics::Orientation o = physics::makeOrientation(x[9], x[10], x[11]);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) scene.orientation[3 * i + j] = o.R(i, j);
      scene.centre = {x[7], x[8], scene.radius};
      scene.massPoint = {x[0], x[1]};
      scene.proxyPosition = snap.proxyPosition;
      scene.force = snap.handForce;
    }
    f.renderer->render(scene, size.width, size.height);
    f.window->swap();
    glFinish();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::uint64_t ticks = loop.ticks() - ticks0;
  loop.stop();
  const haptics::LoopTimingSummary t = loop.timingSummary();
  state.counters["servo_hz"] = double(ticks) / seconds;
  state.counters["missed_ticks"] = double(t.missedTicks);
  state.counters["late_p99_us"] = t.latenessP99 * 1e6;
  state.counters["late_max_us"] = t.latenessMax * 1e6;
}
BENCHMARK(BM_RenderFrameWindowWithServo)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()
    ->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
