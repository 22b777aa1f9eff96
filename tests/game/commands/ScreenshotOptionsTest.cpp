#include "game/commands/ScreenshotOptions.h"

#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

TEST(ScreenshotOptionsTest, ParsesEveryFlag) {
  const ScreenshotOptionsResult r =
      parseScreenshotOptions({"level.lua", "--out=a.png", "--state", "x_p=0.01,psi=-1.5", "--camera", "top",
                              "--zoom", "2.5", "--size", "640x480", "--proxy", "0.01,-0.02,0.05", "--frames", "30"});
  ASSERT_EQ(r.error, "");
  const ScreenshotOptions& o = r.options;
  EXPECT_EQ(o.levelPath, "level.lua");
  EXPECT_EQ(o.outPath, "a.png");
  ASSERT_EQ(o.state.size(), 2u);
  EXPECT_EQ(o.state[0], (std::pair<int, double>{0, 0.01}));
  EXPECT_EQ(o.state[1], (std::pair<int, double>{11, -1.5}));
  EXPECT_EQ(o.camera, render::CameraMode::Top);
  EXPECT_EQ(o.zoom, 2.5);
  EXPECT_EQ(o.width, 640);
  EXPECT_EQ(o.height, 480);
  ASSERT_TRUE(o.proxy);
  EXPECT_EQ((*o.proxy)[1], -0.02);
  EXPECT_EQ(o.frames, 30);
}

TEST(ScreenshotOptionsTest, DefaultsAreAFollowCameraAt1280x720) {
  const ScreenshotOptionsResult r = parseScreenshotOptions({"l.lua", "--out", "a.png"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.camera, render::CameraMode::Follow);
  EXPECT_EQ(r.options.width, 1280);
  EXPECT_EQ(r.options.height, 720);
  EXPECT_FALSE(r.options.proxy);
}

TEST(ScreenshotOptionsTest, BadInputNamesTheFlag) {
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {{"l.lua"}, "missing --out"},
      {{"--out", "a.png"}, "missing LEVEL"},
      {{"l.lua", "--out", "a.png", "--state", "spin=1"}, "unknown state variable 'spin'"},
      {{"l.lua", "--out", "a.png", "--state", "psi=nan"}, "psi needs a finite number"},
      {{"l.lua", "--out", "a.png", "--state", "psi"}, "not name=value"},
      {{"l.lua", "--out", "a.png", "--camera", "side"}, "--camera"},
      {{"l.lua", "--out", "a.png", "--size", "100"}, "--size"},
      {{"l.lua", "--out", "a.png", "--size", "0x100"}, "--size"},
      {{"l.lua", "--out", "a.png", "--zoom", "-1"}, "--zoom"},
      {{"l.lua", "--out", "a.png", "--proxy", "1,2"}, "--proxy"},
      {{"l.lua", "--out", "a.png", "--frames", "0"}, "--frames"},
      {{"l.lua", "--out", "a.png", "--bogus", "1"}, "unknown flag '--bogus'"},
      {{"l.lua", "m.lua", "--out", "a.png"}, "unexpected argument 'm.lua' (only one level)"},
      {{"l.lua", "--out"}, "--out needs a value"},
  };
  for (const auto& [args, expected] : cases) {
    const ScreenshotOptionsResult r = parseScreenshotOptions(args);
    EXPECT_NE(r.error.find(expected), std::string::npos) << "'" << r.error << "' lacks '" << expected << "'";
  }
}

}  // namespace
}  // namespace hemiroll::game
