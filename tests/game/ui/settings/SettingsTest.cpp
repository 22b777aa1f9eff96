// game/ui/settings/Settings: the player's override of the force method and gains,
// applied as a protocol's overrides are (task::overriddenCoupling).

#include "game/ui/settings/Settings.h"

#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

// A level's own: M2, kr 100 N/m, kv 4 N s/m, alpha 1.5.
physics::CouplingDef levelCoupling() { return {physics::ForceMethod::M2, 100.0, 4.0, 1.5, false}; }

TEST(Settings, WithoutTheOverrideTheLevelsCouplingIsUsed) {
  Settings s;
  s.method = 0;
  const physics::CouplingDef c = couplingFor(s, levelCoupling());
  EXPECT_EQ(c.method, physics::ForceMethod::M2);
  EXPECT_EQ(c.stiffness, 100.0);
}

TEST(Settings, TheOverrideSetsMethodAndEveryGain) {
  Settings s;
  s.overrideCoupling = true;
  s.stiffness = 300.0;
  s.damping = 12.0;
  s.alpha = 2.5;
  const char* names[] = {"M1", "M2", "M3", "visual"};
  for (int method = 0; method < 4; ++method) {
    s.method = method;
    const physics::CouplingDef c = couplingFor(s, levelCoupling());
    EXPECT_EQ(c.visualOnly, method == 3);
    EXPECT_STREQ(methodLabel(method), names[method]);
    EXPECT_EQ(c.method, method == 0   ? physics::ForceMethod::M1
                        : method == 1 ? physics::ForceMethod::M2
                                      : physics::ForceMethod::M3);
    EXPECT_EQ(c.stiffness, 300.0);
    EXPECT_EQ(c.damping, 12.0);
    EXPECT_EQ(c.alpha, 2.5);
  }
}

// The hand feel opens the factory's "mouse-hand"; other devices as they are.
TEST(Settings, TheHandFeelPlaysTheFactorysMouseHand) {
  Settings s;
  EXPECT_EQ(playDeviceName(s), "mouse");
  s.mouseFeel = MouseFeel::Hand;
  EXPECT_EQ(playDeviceName(s), "mouse-hand");
  s.device = "joystick";
  EXPECT_EQ(playDeviceName(s), "joystick");
}

}  // namespace
}  // namespace hemiroll::game
