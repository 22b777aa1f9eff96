// `hemiroll screenshot` end to end (game/commands/ScreenshotCommand): in
// process under Xvfb, and as a child without a display. Lives with the
// render tests because it needs their virtual display.
#include "game/commands/ScreenshotCommand.h"

#include <gtest/gtest.h>

#include <set>

#include "engine/render/Image.h"
#include "game/commands/ExitCode.h"
#include "tests/render/support/GlTestContext.h"
#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

const std::string kLevel = std::string(HEMIROLL_SOURCE_DIR) + "/levels/paper_reaching.lua";

// The test binary lives far from assets/; point the command at the checkout's.
void useSourceAssets() { setenv("HEMIROLL_ASSETS", HEMIROLL_SOURCE_DIR "/assets", 1); }

TEST(ScreenshotCommandTest, WritesAPngOfTheAskedSize) {
  test::TempDirectory dir;
  const std::string out = (dir.path() / "shot.png").string();
  useSourceAssets();
  testing::internal::CaptureStderr();
  ASSERT_EQ(runScreenshotCommand({kLevel, "--out", out, "--size", "200x150", "--camera", "top", "--state",
                                  "u_a=0.01,psi=0.5", "--proxy", "0.01,0.0,0.06"}),
            kExitOk);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(err.find("note:"), std::string::npos) << err;  // every asset was found
  const render::Image image = render::readPng(out);
  EXPECT_EQ(image.width, 200);
  EXPECT_EQ(image.height, 150);
  // Not an empty frame: the sky, the floor and the hemisphere give many colours.
  std::set<std::uint32_t> colours;
  for (std::size_t p = 0; p < image.rgba.size(); p += 4)
    colours.insert(image.rgba[p] << 16 | image.rgba[p + 1] << 8 | image.rgba[p + 2]);
  EXPECT_GT(colours.size(), 50u);
}

TEST(ScreenshotCommandTest, BadInputIsExitTwo) {
  test::TempDirectory dir;
  const std::string out = (dir.path() / "x.png").string();
  EXPECT_EQ(runScreenshotCommand({kLevel, "--out", out, "--state", "nonsense=1"}), kExitUsage);
  EXPECT_EQ(runScreenshotCommand({kLevel}), kExitUsage);
  const std::string broken = dir.write("broken.lua", "return {\n  name = 'x',\n  params = { R = -1 },\n}\n");
  testing::internal::CaptureStderr();
  EXPECT_EQ(runScreenshotCommand({broken, "--out", out}), kExitUsage);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find(broken + ":3:"), std::string::npos) << err;
}

TEST(ScreenshotCommandTest, AnUnwritableOutputIsExitOne) {
  test::useGlContext();  // the command's own window comes and goes; the shared one stays
  EXPECT_EQ(runScreenshotCommand({kLevel, "--out", "/nonexistent-dir/x.png", "--size", "32x32"}), kExitFailure);
}

TEST(ScreenshotCommandTest, WithoutADisplayItSaysHowToRunHeadless) {
  test::TempDirectory dir;
  const test::ProcessResult r =
      test::runProcess("/usr/bin/env", {"-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", "-u", "SDL_VIDEODRIVER",
                                        HEMIROLL_BINARY, "screenshot", kLevel, "--out", (dir.path() / "x.png").string()});
  EXPECT_EQ(r.exitCode, kExitFailure);
  EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("hemiroll run"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hemiroll::game
