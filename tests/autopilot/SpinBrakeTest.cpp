// engine/autopilot/SpinBrake on the engine's own model (PlantModel, stepped
// as the servo loop steps it): the rest keeps its spin however long it is
// held; the brake the law chooses takes it out, on the paper's body and on
// other bodies and couplings, and leaves the hemisphere near where it was.

#include "engine/autopilot/SpinBrake.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/autopilot/PlantModel.h"
#include "engine/autopilot/UprightContact.h"

namespace hemiroll::autopilot {
namespace {

using physics::Vec2;
using physics::Vec3;

constexpr double kDt = 0.001;
constexpr double kPaperSpinBand = 0.01;  // the paper's task: each omega component within 0.01 rad/s

struct Body {
  physics::HemisphereParams params;
  physics::CouplingDef coupling;
};

struct Braked {
  double restSpin = 0.0;     // J before any brake [rad/s]
  double heldSpin = 0.0;     // J after holding the rest as long as the brakes took [rad/s]
  double brakedSpin = 0.0;   // J after the brakes [rad/s]
  int brakes = 0;
  double seconds = 0.0;      // from the first brake to the last reading [s]
  double drift = 0.0;        // how far c_up moved meanwhile [m]
  bool fell = false;
};

// A rest leaning towards a target 2 mm off c_up, spinning at `spin`, then
// up to `most` brakes the law chooses (each: circle, stop, settle 4 s),
// while |J| >= `goal`. `brake` false: the rest is held as long instead.
Braked play(const Body& body, double spin, double goal, int most, bool brake) {
  const SettleGain gain = settleGainFor(body.params, body.coupling, kDt);
  const HelixParams helix;
  const SpinBrakeTable table = spinBrakeTableFor(body.params, body.coupling, helix, gain, kDt);
  EXPECT_GT(table.rows, 0);
  PlantModel plant(body.params, body.coupling, kDt);
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x[physics::force_slot::w_z] = spin;
  plant.reset(x, 0.0);
  const physics::ModelConstants& constants = plant.constants();
  HelixPolicy law(constants, helix, kDt);
  law.setSettleGain(gain);
  Goal g;
  g.set[7] = g.set[8] = true;
  g.target[7] = 0.002;
  g.tolerance[7] = g.tolerance[8] = 0.004;
  law.setGoal(g);
  Vec3 last(0.0, 0.0, body.params.radius);
  law.startAt(last);
  law.settleNow();
  Braked out;
  const auto run = [&](double seconds) {
    for (long long k = 0; k < std::llround(seconds / kDt) && !out.fell; ++k) {
      const Vec3 proxy = law.proxyFor(plant.state());
      out.fell = plant.tick(proxy, (proxy - last) / kDt) != physics::DomainEvent::None;
      last = proxy;
    }
    return plant.state()[physics::force_slot::w_z];
  };
  out.restSpin = run(4.0);
  const Vec2 upright = uprightContact(constants, plant.state()).point;
  const double start = plant.time();
  double j = out.restSpin;
  for (; out.brakes < most && std::abs(j) >= goal && !out.fell; ++out.brakes) {
    const SpinBrakeCommand c = spinBrakeFor(table, j);
    EXPECT_TRUE(c.valid);
    std::printf("[spin brake] J %+.4f rad/s: a %.2f mm circle at %+.2f rad/s\n", j, c.amplitude * 1e3, c.rate);
    if (brake) startBrake(law, c);
    j = run(table.lock + 4.0);
  }
  out.seconds = plant.time() - start;
  (brake ? out.brakedSpin : out.heldSpin) = j;
  out.drift = (uprightContact(constants, plant.state()).point - upright).norm();
  std::printf("[spin brake] J %+.4f -> %+.4f rad/s, %d brakes, %.1f s, c_up moved %.1f mm (table: %d sizes, %.1f-%.1f mm)\n",
              out.restSpin, j, out.brakes, out.seconds, out.drift * 1e3, table.rows, table.amplitude[0] * 1e3,
              table.amplitude[static_cast<std::size_t>(std::max(0, table.rows - 1))] * 1e3);
  return out;
}

void expectBraked(const Body& body, double spin) {
  const Braked braked = play(body, spin, 0.5 * kPaperSpinBand, 3, true);
  const Braked held = play(body, spin, 0.5 * kPaperSpinBand, braked.brakes, false);
  EXPECT_FALSE(braked.fell);
  EXPECT_FALSE(held.fell);
  // Held, the rest keeps its spin (within a tenth); braked, it is within
  // half the paper's band; and the hemisphere is still within the paper's
  // 4 mm contact band of where it was.
  EXPECT_NEAR(held.heldSpin, held.restSpin, 0.1 * std::abs(held.restSpin));
  EXPECT_GT(std::abs(held.heldSpin), kPaperSpinBand);
  EXPECT_LT(std::abs(braked.brakedSpin), 0.5 * kPaperSpinBand);
  EXPECT_LT(braked.drift, 0.004);
}

TEST(SpinBrake, AStopLeavesSpinInTheCirclesSenseGrowingWithItsSize) {
  const Body paper;
  const SpinBrakeTable t =
      spinBrakeTableFor(paper.params, paper.coupling, HelixParams{}, settleGainFor(paper.params, paper.coupling, kDt), kDt);
  ASSERT_GE(t.rows, 3);
  // Measured: +0.004, +0.026, +0.098 rad/s after 1, 1.5 and 2 mm circles.
  EXPECT_GT(t.change[0], 0.0);
  for (int i = 1; i < t.rows; ++i) EXPECT_GT(t.change[static_cast<std::size_t>(i)], t.change[static_cast<std::size_t>(i - 1)]);
  const SpinBrakeCommand c = spinBrakeFor(t, 0.5 * (t.change[0] + t.change[1]));
  EXPECT_LT(c.rate, 0.0);  // against the spin
  EXPECT_GT(c.amplitude, t.amplitude[0]);
  EXPECT_LT(c.amplitude, t.amplitude[1]);
  EXPECT_GT(spinBrakeFor(t, -0.01).rate, 0.0);
  EXPECT_FALSE(spinBrakeFor(SpinBrakeTable{}, 0.01).valid);
}

TEST(SpinBrake, TakesTheRestsSpinOutOnThePapersBody) {
  expectBraked(Body{}, 0.03);
  expectBraked(Body{}, -0.02);
}

TEST(SpinBrake, TakesTheRestsSpinOutOnAnotherBody) {
  Body small;  // R 3 cm, a 0.2 kg shell, a 0.5 kg point
  small.params.radius = 0.03;
  small.params.shellMass = 0.2;
  small.params.pointMass = 0.5;
  expectBraked(small, 0.03);
}

TEST(SpinBrake, TakesTheRestsSpinOutWithAStifferCoupling) {
  Body stiff;  // the paper's body, k_r 400 N/m
  stiff.coupling.stiffness = 400.0;
  expectBraked(stiff, 0.03);
}

}  // namespace
}  // namespace hemiroll::autopilot
