// engine/physics/LastSampleTrajectory: answering a repeated time from memory
// gives the bits a fresh evaluation gives, so a run through it is the plain
// run bit for bit, with fewer evaluations of the rose.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include "engine/physics/IntegratorRegistry.h"
#include "engine/physics/LastSampleTrajectory.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "engine/physics/RoseDrive.h"
#include "engine/physics/Stepper.h"
#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {
namespace {

using physics::BodyState;
using physics::LastSampleTrajectory;
using physics::MassPointTrajectory;

bool sameBits(const MassPointTrajectory::Sample& a, const MassPointTrajectory::Sample& b) {
  return std::memcmp(a.p.data(), b.p.data(), sizeof(double) * 2) == 0 &&
         std::memcmp(a.pDot.data(), b.pDot.data(), sizeof(double) * 2) == 0 &&
         std::memcmp(a.pDDot.data(), b.pDDot.data(), sizeof(double) * 2) == 0;
}

// p = (t, 1/t): +0 and -0 give +inf and -inf; counts its evaluations.
struct CountingTrajectory final : MassPointTrajectory {
  mutable int evaluations = 0;
  Sample at(double t) const override {
    ++evaluations;
    return {Vec2(t, 1.0 / t), Vec2(2.0 * t, 0.0), Vec2::Zero()};
  }
};

TEST(LastSampleTrajectory, AnswersEveryTimeAsTheSourceDoesAndEvaluatesOnlyNewTimes) {
  CountingTrajectory source;
  const LastSampleTrajectory remembered(source);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double times[] = {0.0, 0.0, -0.0, -0.0, 0.0, 0.5, 0.5, 0.5 + 1e-17, 0.25, nan, nan, 1.0};
  int fresh = 0;
  double last = 7.0;
  for (const double t : times) {
    EXPECT_TRUE(sameBits(remembered.at(t), CountingTrajectory{}.at(t))) << "t = " << t;
    fresh += std::memcmp(&t, &last, sizeof t) != 0 ? 1 : 0;
    last = t;
  }
  EXPECT_EQ(source.evaluations, fresh);  // 0.5 + 1e-17 is 0.5; NaN has the same bits twice
}

// The rose from rest, the paper's drive, stepped as ScenarioRun steps it
// (rk4 with the clock put back on the grid; dop853 to each grid time), with
// the rose plain and remembered: the same states bit for bit at every step.
void expectSameRun(const std::string& integratorName) {
  const physics::RoseDrive rose(physics::RoseDef{});
  const LastSampleTrajectory remembered(rose);
  const physics::PrescribedDriveSystem plainSystem(paperParams(), rose), rememberedSystem(paperParams(), remembered);
  auto plainIntegrator = physics::IntegratorRegistry::builtin().make<8>(integratorName);
  auto rememberedIntegrator = physics::IntegratorRegistry::builtin().make<8>(integratorName);
  const BodyState x0 = BodyState::Zero();
  physics::Stepper<8> plain(plainSystem, *plainIntegrator, x0), fast(rememberedSystem, *rememberedIntegrator, x0);
  constexpr double dt = 1e-3;
  for (int i = 1; i <= 3000; ++i) {
    const double target = i * dt;
    const physics::StepReport a = plain.adaptive() ? plain.advanceTo(target) : plain.advance(dt);
    const physics::StepReport b = fast.adaptive() ? fast.advanceTo(target) : fast.advance(dt);
    ASSERT_EQ(a.event, b.event) << integratorName << " step " << i;
    if (!plain.adaptive()) {
      plain.reset(plain.state(), target);
      fast.reset(fast.state(), target);
    }
    ASSERT_EQ(std::memcmp(plain.state().data(), fast.state().data(), sizeof(double) * 8), 0)
        << integratorName << " step " << i;
    if (a.event != physics::DomainEvent::None) break;
  }
}

TEST(LastSampleTrajectory, RunsOfTheRoseAreThePlainRunsBitForBit) {
  expectSameRun("rk4");
  expectSameRun("dop853");
}

}  // namespace
}  // namespace hemiroll::test
