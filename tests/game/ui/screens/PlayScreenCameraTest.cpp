// The play screen's cameras in a real window (Xvfb + llvmpipe): the arrow
// keys turn the orbit camera, and the mouse's strokes turn with it, so that
// a stroke to the right moves the proxy to the right on screen.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/platform/KeyNames.h"
#include "engine/render/Camera.h"
#include "game/ui/app/App.h"
#include "game/ui/screens/PlayScreen.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

TEST(PlayScreenCameraTest, ArrowKeysTurnTheOrbitCameraAndTheStrokesTurnWithIt) {
  test::TempDirectory dir;
  AppDef def;
  def.hidden = true;
  def.vsync = false;
  def.scoresFile = (dir.path() / "scores.sqlite").string();
  def.settingsFile = (dir.path() / "settings.json").string();  // not the user's
  App app(def);
  app.settings().camera = render::CameraMode::Orbit;
  const double yaw0 = app.settings().orbitYaw;
  app.screens().push(std::make_unique<PlayScreen>(app, HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua"));
  app.frame();
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();

  for (int i = 0; i < 3; ++i) app.inject(platform::keyDownEvent("Right"));
  app.inject(platform::keyDownEvent("Up"));
  app.frame();
  EXPECT_NEAR(app.settings().orbitYaw, yaw0 + 0.3, 1e-12);
  EXPECT_NEAR(app.settings().orbitPitch, Settings{}.orbitPitch + 0.05, 1e-12);

  // A stroke to the right moves the proxy along the camera's screen right.
  const haptics::Vec3 before = play->session()->pointerScene();
  platform::InputEvent stroke;
  stroke.type = platform::InputType::PointerMove;
  stroke.dx = 40.0;
  app.inject(stroke);
  app.frame();
  const haptics::Vec3 moved = play->session()->pointerScene() - before;
  render::CameraDef camera;
  camera.mode = render::CameraMode::Orbit;
  camera.yaw = app.settings().orbitYaw;
  const double heading = render::screenRightHeading(camera);
  ASSERT_GT(moved.head<2>().norm(), 0.0);
  EXPECT_NEAR(std::atan2(moved.y(), moved.x()), heading, 1e-9);

  // Other cameras ignore the arrows.
  app.settings().camera = render::CameraMode::Follow;
  app.inject(platform::keyDownEvent("Right"));
  app.frame();
  EXPECT_NEAR(app.settings().orbitYaw, yaw0 + 0.3, 1e-12);
}

}  // namespace
}  // namespace hemiroll::game
