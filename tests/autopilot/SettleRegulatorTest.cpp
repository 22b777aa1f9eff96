// engine/autopilot/SettleRegulator on the engine's own model (PlantModel,
// stepped as the servo loop steps it): it takes out the light shell's
// rocking that a still proxy leaves for seconds, comes to rest at the lean it
// is given, leaves spin about the axis as it is (the limit SettleRegulator.h
// states: the landing must take spin out), and is offered only for bodies
// where the model shows it reaching its rest.

#include "engine/autopilot/SettleRegulator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/autopilot/PlantModel.h"
#include "engine/autopilot/UprightContact.h"
#include "engine/physics/ForceCoupling.h"

namespace hemiroll::autopilot {
namespace {

using physics::Vec2;
using physics::Vec3;

constexpr double kDt = 0.001;

struct Settled {
  double rocking = 0.0;  // largest |(w_x, w_y)| over the last second [rad/s]
  physics::ForceDrivenState final = physics::ForceDrivenState::Zero();
};

// The paper's body from `start` for `seconds`, the proxy either still over
// the face centre or moved by the regulator towards the rest at `lean`.
Settled play(const physics::ForceDrivenState& start, double seconds, bool regulate, const Vec2& lean = Vec2::Zero(),
         const physics::HemisphereParams& params = {}) {
  const physics::CouplingDef coupling;
  const SettleGain gain = settleGainFor(params, coupling, kDt);
  EXPECT_TRUE(!regulate || gain.valid);
  const physics::ModelConstants constants(params);
  PlantModel plant(params, coupling, kDt);
  plant.reset(start, 0.0);
  Vec2 proxy(start[physics::force_slot::u_a], start[physics::force_slot::v_a]);
  Settled out;
  const long long ticks = std::llround(seconds / kDt);
  for (long long k = 0; k < ticks; ++k) {
    const Vec2 step = regulate ? settleStep(gain, constants, plant.state(), proxy, lean, 0.25 * kDt) : Vec2::Zero();
    proxy += step;
    const physics::DomainEvent event =
        plant.tick(Vec3(proxy.x(), proxy.y(), params.radius), Vec3(step.x() / kDt, step.y() / kDt, 0.0));
    EXPECT_EQ(event, physics::DomainEvent::None) << "t = " << plant.time();
    if (event != physics::DomainEvent::None) break;
    if (k >= ticks - std::llround(1.0 / kDt))
      out.rocking = std::max(out.rocking, std::hypot(plant.state()[physics::force_slot::w_x],
                                                     plant.state()[physics::force_slot::w_y]));
  }
  out.final = plant.state();
  return out;
}

// Upright on the paper's body, the shell knocked into rocking.
physics::ForceDrivenState rocking(double wz = 0.0) {
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x[physics::force_slot::w_x] = 0.05;
  x[physics::force_slot::w_y] = -0.03;
  x[physics::force_slot::w_z] = wz;
  return x;
}

TEST(SettleRegulator, TakesOutTheRockingAStillProxyLeaves) {
  const Settled still = play(rocking(), 3.0, false);
  const Settled regulated = play(rocking(), 3.0, true);
  // Measured: 0.025 rad/s with the proxy still (the rocking decays over
  // about 12 s), 0.0001 regulated. The paper's band on each component of
  // omega is 0.01: still, the rocking is outside it after 3 s; regulated, it
  // is below a tenth of it.
  EXPECT_GT(still.rocking, 0.01);
  EXPECT_LT(regulated.rocking, 0.001);
}

TEST(SettleRegulator, ComesToRestAtTheLeanItIsGiven) {
  const Vec2 lean = std::sin(0.03) * Vec2(std::cos(2.0), std::sin(2.0));
  const Settled r = play(physics::ForceDrivenState::Zero(), 6.0, true, lean);
  const physics::ModelConstants constants{physics::HemisphereParams{}};
  const Vec3 normal = faceNormal(constants, r.final);
  // The rests near upright are taken as a line through the one linearised
  // about (lean 0.05): measured 3 % short of the lean asked; 5 % allowed.
  EXPECT_NEAR(std::hypot(normal.x(), normal.y()), lean.norm(), 0.05 * lean.norm());
  EXPECT_NEAR(std::atan2(normal.y(), normal.x()), 2.0, 0.01);
  EXPECT_LT(r.rocking, 0.001);
}

TEST(SettleRegulator, LeavesSpinAboutTheAxisAsItIs) {
  const Vec2 lean(std::sin(0.04), 0.0);
  const Settled r = play(rocking(0.02), 5.0, true, lean);
  // The rocking goes (below a tenth of the paper's band), the spin stays
  // within a tenth of what it was (measured: 0.02 -> 0.01995).
  EXPECT_LT(r.rocking, 0.002);
  EXPECT_NEAR(r.final[physics::force_slot::w_z], 0.02, 0.002);
}

TEST(SettleRegulator, IsOfferedOnlyWhereTheModelShowsItReachingItsRest) {
  const physics::CouplingDef coupling;
  EXPECT_TRUE(settleGainFor(physics::HemisphereParams{}, coupling, kDt).valid);
  physics::HemisphereParams heavyShell;  // the tutorials' 02 and 03
  heavyShell.shellMass = 1.0;
  heavyShell.pointMass = 0.2;
  EXPECT_FALSE(settleGainFor(heavyShell, coupling, kDt).valid);
}

}  // namespace
}  // namespace hemiroll::autopilot
