// Stepper.h, sleeping: a scene at an exact fixed point of the step map stops
// integrating and wakes when its input changes, and a slept run is
// bit-identical to one that never sleeps.

#include <gtest/gtest.h>

#include <cstring>
#include <functional>

#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/Stepper.h"
#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {
namespace {

using physics::ForceDrivenState;
using physics::ProxyPose;

// RK4 that declares history, so a Stepper never lets it sleep: the reference
// that steps every time.
class AlwaysStepRk4 final : public physics::Integrator<12> {
 public:
  std::string_view name() const override { return "rk4-always-steps"; }
  int order() const override { return 4; }
  void step(const physics::OdeSystem<12>& f, double t, ForceDrivenState& x, double h) override {
    inner_.step(f, t, x, h);
  }

 private:
  physics::RungeKutta4<12> inner_;
};

bool sameBits(const ForceDrivenState& a, const ForceDrivenState& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 12) == 0;
}

// Runs `steps` steps of h with `input(i, system)` applied before step i, once
// sleeping and once always stepping; expects identical states and times at
// every step, and returns how many steps the sleeping run skipped.
// The reference's steps that left its state bit for bit as it was: the only
// steps a sleeping stepper may skip.
long long lastUnchangedSteps = 0;

long long compareRuns(const ForceDrivenState& x0, int steps, double h,
                      const std::function<void(int, physics::ForceDrivenSystem&)>& input) {
  lastUnchangedSteps = 0;
  physics::ForceDrivenSystem sleepy(paperParams()), awake(paperParams());
  physics::RungeKutta4<12> rk4;
  AlwaysStepRk4 reference;
  physics::Stepper<12> a(sleepy, rk4, x0), b(awake, reference, x0);
  for (int i = 0; i < steps; ++i) {
    input(i, sleepy);
    input(i, awake);
    const ForceDrivenState before = b.state();
    a.advance(h);
    b.advance(h);
    if (sameBits(before, b.state())) ++lastUnchangedSteps;
    EXPECT_TRUE(sameBits(a.state(), b.state())) << "step " << i;
    EXPECT_EQ(a.time(), b.time()) << "step " << i;
    if (!sameBits(a.state(), b.state())) break;
  }
  EXPECT_EQ(b.sleptSteps(), 0);
  return a.sleptSteps();
}

TEST(StepperSleep, RestingFreeSceneSleepsAndMatchesBitForBit) {
  // Upright, mass point at the face centre, at rest: every rate is zero.
  const long long slept = compareRuns(ForceDrivenState::Zero(), 1000, 1e-3, [](int i, physics::ForceDrivenSystem& s) {
    if (i == 0) s.setFree();
  });
  // The first step finds the fixed point; the other 999 are skipped.
  EXPECT_EQ(slept, 999);
}

TEST(StepperSleep, HeldProxyAtRestSleepsAndWakesOnANewPose) {
  const ProxyPose rest{Vec3(0.0, 0.0, 0.04), Vec3::Zero()};  // at the mass point: no force
  const ProxyPose moved{Vec3(0.003, -0.001, 0.04), Vec3::Zero()};
  const long long slept = compareRuns(ForceDrivenState::Zero(), 2000, 1e-3, [&](int i, physics::ForceDrivenSystem& s) {
    if (i == 0) s.setCoupling(physics::CouplingDef{});
    // The servo loop holds the same pose every tick: no wake-up...
    s.holdProxy(i < 1000 ? rest : moved);
  });
  // ...until step 1000 moves it: 999 skipped before, and the scene moves after.
  EXPECT_EQ(slept, 999);
}

TEST(StepperSleep, WakesOnAFaceForceAndOnAChangedStep) {
  physics::ForceDrivenSystem sys(paperParams());
  physics::RungeKutta4<12> rk4;
  physics::Stepper<12> stepper(sys, rk4, ForceDrivenState::Zero());
  stepper.advance(1e-3);
  EXPECT_TRUE(stepper.sleeping());
  stepper.advance(5e-4);  // another step length: must really step (and finds the fixed point again)
  EXPECT_EQ(stepper.sleptSteps(), 0);
  sys.setFaceForce(physics::Vec2(0.1, 0.0));
  stepper.advance(5e-4);
  EXPECT_FALSE(stepper.sleeping());
  EXPECT_NE(stepper.state()[2], 0.0);  // the force accelerated the mass point
}

TEST(StepperSleep, NearRestIsNotRest) {
  // Static tilt for p held at 4 mm is a fixed point only to round-off: the
  // rates are tiny but not zero, so the stepper must keep stepping unless
  // RK4 itself returns the same bits (and then the reference does too).
  ForceDrivenState x = ForceDrivenState::Zero();
  x[0] = 0.004;
  x[10] = -5.53 * kDeg;
  const long long slept = compareRuns(x, 500, 1e-3, [](int i, physics::ForceDrivenSystem& s) {
    if (i == 0) {
      s.setCoupling(physics::CouplingDef{});
      s.holdProxy({Vec3(0.004, 0.0, 0.04), Vec3::Zero()});
    }
  });
  // Skipped only where the always-stepping reference changed no bit.
  EXPECT_LE(slept, lastUnchangedSteps);
  // And the state is near rest, not at it: most steps still change it.
  EXPECT_LT(lastUnchangedSteps, 250);
}

TEST(StepperSleep, ProxyTrajectoryNeverSleeps) {
  struct Still final : physics::ProxyTrajectory {
    ProxyPose at(double) const override { return {Vec3(0.0, 0.0, 0.04), Vec3::Zero()}; }
  } still;
  physics::ForceDrivenSystem sys(paperParams());
  sys.setCoupling(physics::CouplingDef{}, still);
  physics::RungeKutta4<12> rk4;
  physics::Stepper<12> stepper(sys, rk4, ForceDrivenState::Zero());
  for (int i = 0; i < 10; ++i) stepper.advance(1e-3);
  // The function of time could change at any moment: not autonomous.
  EXPECT_EQ(stepper.sleptSteps(), 0);
}

TEST(StepperSleep, NegativeZeroInTheStartStillMatches) {
  // -0.0 + 0.0 is +0.0: the first step changes the bits, so sleep starts one
  // step later, and the runs still agree bit for bit.
  ForceDrivenState x = ForceDrivenState::Zero();
  x[2] = -0.0;
  x[7] = -0.0;
  const long long slept = compareRuns(x, 100, 1e-3, [](int, physics::ForceDrivenSystem&) {});
  EXPECT_EQ(slept, 98);
}

}  // namespace
}  // namespace hemiroll::test
