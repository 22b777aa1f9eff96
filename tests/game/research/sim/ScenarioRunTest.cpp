// game/research/sim/ScenarioRun: which rows a run produces, independent of the physics.

#include "game/research/sim/ScenarioRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

namespace hemiroll::game {
namespace {

task::ScenarioDef roseScenario() {
  task::ScenarioDef def;
  def.drive.kind = task::DriveKind::Rose;
  return def;
}

std::vector<TrajectoryRow> rowsOf(const task::ScenarioDef& def, const RunSettings& s, RunSummary* summary = nullptr) {
  std::vector<TrajectoryRow> rows;
  const RunSummary r = ScenarioRun(def, s).run([&](const TrajectoryRow& row) { rows.push_back(row); });
  if (summary) *summary = r;
  return rows;
}

TEST(ScenarioRun, StepCountRoundsWholeRatiosAndCoversTheRest) {
  EXPECT_EQ(ScenarioRun::stepCount({35.0, 0.001, "rk4", 1}), 35000);
  EXPECT_EQ(ScenarioRun::stepCount({0.1, 0.001, "rk4", 1}), 100);
  EXPECT_EQ(ScenarioRun::stepCount({0.1005, 0.001, "rk4", 1}), 101);  // last step shortened
  EXPECT_EQ(ScenarioRun::stepCount({0.0005, 0.001, "rk4", 1}), 1);
}

TEST(ScenarioRun, RowsAtEveryNthStepPlusFirstAndLast) {
  RunSummary summary;
  const auto rows = rowsOf(roseScenario(), {0.1, 0.001, "rk4", 7}, &summary);
  ASSERT_EQ(summary.event, physics::DomainEvent::None);
  EXPECT_EQ(summary.steps, 100);
  ASSERT_EQ(rows.size(), 1u + 100 / 7 + 1);  // 0, 7, ..., 98, and 100
  EXPECT_EQ(rows.front().time, 0.0);
  for (std::size_t i = 1; i + 1 < rows.size(); ++i) EXPECT_DOUBLE_EQ(rows[i].time, 0.007 * static_cast<double>(i));
  EXPECT_EQ(rows.back().time, 0.1);
}

TEST(ScenarioRun, SubsampledRowsEqualTheFullRun) {
  const auto all = rowsOf(roseScenario(), {0.05, 0.001, "rk4", 1});
  const auto some = rowsOf(roseScenario(), {0.05, 0.001, "rk4", 10});
  ASSERT_EQ(all.size(), 51u);
  ASSERT_EQ(some.size(), 6u);
  for (std::size_t i = 0; i < some.size(); ++i) {
    EXPECT_EQ(some[i].time, all[10 * i].time);
    EXPECT_EQ(some[i].state, all[10 * i].state);
    EXPECT_EQ(some[i].energy, all[10 * i].energy);
  }
}

TEST(ScenarioRun, ShortenedLastStepEndsAtTheDuration) {
  const auto rows = rowsOf(roseScenario(), {0.0105, 0.001, "rk4", 1});
  ASSERT_EQ(rows.size(), 12u);
  EXPECT_EQ(rows.back().time, 0.0105);
}

TEST(ScenarioRun, RoseRowsCarryTheCurveAndTheDrivingForce) {
  const task::ScenarioDef def = roseScenario();
  const auto rows = rowsOf(def, {0.01, 0.001, "rk4", 1});
  // p(0) = (r1 + r2, 0) by eqs. (49)-(50) at phi = 0.
  EXPECT_EQ(rows.front().state[physics::force_slot::x_p], def.drive.rose.r1 + def.drive.rose.r2);
  EXPECT_EQ(rows.front().state[physics::force_slot::y_p], 0.0);
  EXPECT_NE(rows.front().faceForce.norm(), 0.0);
  EXPECT_EQ(rows.front().handForce, physics::Vec3::Zero());
}

// StateOnly rows (a sweep point's) are the full rows' time, position and
// body state, bit for bit, with nothing else: from rest (chaotic, where any
// difference would grow) and in a run that tips over (the event row too).
TEST(ScenarioRun, StateOnlyRoseRowsAreTheFullRowsWithoutTheRest) {
  task::ScenarioDef tipping = roseScenario();
  tipping.drive.rose.r1 = 0.03;
  tipping.drive.rose.omega = -3.0;
  bool sawEvent = false;
  for (const task::ScenarioDef& def : {roseScenario(), tipping}) {
    for (const char* integrator : {"rk4", "dop853"}) {
      const RunSettings settings{2.0, 0.001, integrator, 10};
      std::vector<TrajectoryRow> full, only;
      const RunSummary a = ScenarioRun(def, settings).run([&](const TrajectoryRow& row) { full.push_back(row); });
      const RunSummary b = ScenarioRun(def, settings, RowContent::StateOnly).run([&](const TrajectoryRow& row) {
        only.push_back(row);
      });
      EXPECT_EQ(a.steps, b.steps);
      EXPECT_EQ(a.event, b.event);
      EXPECT_EQ(std::memcmp(&a.endTime, &b.endTime, sizeof(double)), 0);
      EXPECT_EQ(b.finalEnergy, 0.0);
      sawEvent = sawEvent || a.event != physics::DomainEvent::None;
      ASSERT_EQ(full.size(), only.size()) << integrator;
      for (std::size_t i = 0; i < full.size(); ++i) {
        namespace slot = physics::force_slot;
        physics::ForceDrivenState expected = full[i].state;
        expected[slot::xd_p] = expected[slot::yd_p] = 0.0;
        ASSERT_EQ(std::memcmp(&full[i].time, &only[i].time, sizeof(double)), 0) << integrator << " row " << i;
        ASSERT_EQ(std::memcmp(expected.data(), only[i].state.data(), sizeof(double) * 12), 0)
            << integrator << " row " << i;
        EXPECT_EQ(only[i].energy, 0.0);
        EXPECT_EQ(only[i].faceForce, physics::Vec2::Zero());
      }
    }
  }
  EXPECT_TRUE(sawEvent);  // the second scenario tips over within 2 s
}

TEST(ScenarioRun, InitialStateOutsideTheDomainStopsAtOnce) {
  task::ScenarioDef def = roseScenario();
  def.drive.rose.r1 = 0.05;  // p(0) beyond the face edge R = 0.04
  RunSummary summary;
  const auto rows = rowsOf(def, {1.0, 0.001, "rk4", 1}, &summary);
  EXPECT_EQ(summary.event, physics::DomainEvent::LeftFace);
  EXPECT_EQ(summary.steps, 0);
  EXPECT_EQ(rows.size(), 1u);
}

// hemiroll sim applies the coupling's step policy (CouplingStability.h): a
// coupling that diverges with plain RK4 at 1 ms (m_p = 2 g, M2, k_r = 5000
// N/m, k_v = 10 N s/m: k_v/m_p h = 5, beyond RK4's 2.785) runs stably.
struct HeldAtCentre final : physics::ProxyTrajectory {
  physics::ProxyPose at(double) const override { return {physics::Vec3(0.0, 0.0, 0.04), physics::Vec3::Zero()}; }
};

TEST(ScenarioRun, StiffCouplingIsSubsteppedAndStaysStable) {
  task::ScenarioDef def;
  def.params.pointMass = 0.002;
  def.drive.kind = task::DriveKind::Proxy;
  def.drive.coupling = physics::CouplingDef{physics::ForceMethod::M2, 5000.0, 10.0, 1.0, false};
  def.drive.proxy = std::make_shared<HeldAtCentre>();
  def.initial[0] = 0.002;  // 2 mm off the proxy
  RunSummary summary;
  const auto rows = rowsOf(def, {1.0, 0.001, "rk4", 100}, &summary);
  EXPECT_EQ(summary.event, physics::DomainEvent::None);
  ASSERT_FALSE(rows.empty());
  EXPECT_TRUE(rows.back().state.allFinite());
  // Settled onto the proxy: the coupling's modes decay at ~k_r/k_v = 500 /s
  // and faster, so after 1 s only gravity's sag along the face normal (taken
  // by the face) remains; in-face the point sits at the centre to 1 um.
  EXPECT_LT(std::hypot(rows.back().state[0], rows.back().state[1]), 1e-6);
}

// The quaternion form (RunSettings::orientation) runs the same physics: with
// DOP853 at tol 1e-12 both forms land within ~1e-11 of the exact solution
// over these 3 s (RotationDrivenSystemTest measures 1.4e-13 for 1 s of M3),
// so rows must agree to 1e-9 -- psi included, which the quaternion form
// recovers from q and keeps continuous through several turns (|w_z| of 4 to
// 6 rad/s for 3 s), each crossing the branch cut of atan2.
TEST(ScenarioRun, QuaternionFormGivesTheSameRowsAsContactAngles) {
  task::ScenarioDef spin;
  // Free: a pure spin (any rocking lets the frictionless point slide off the
  // face within a second). The M3 tether exercises the whole dynamics.
  spin.initial[physics::force_slot::w_z] = 6.0;
  spin.drive.kind = task::DriveKind::Free;
  task::ScenarioDef tether;
  tether.drive.kind = task::DriveKind::Proxy;
  tether.drive.coupling = physics::CouplingDef{};  // M3, the paper's gains
  tether.drive.proxy = std::make_shared<HeldAtCentre>();
  tether.initial[physics::force_slot::x_p] = 0.004;
  tether.initial[physics::force_slot::w_z] = -4.0;
  for (const task::ScenarioDef* def : {&spin, &tether}) {
    RunSettings settings{3.0, 0.01, "dop853", 10, 1e-12};
    RunSummary summary;
    const auto angles = rowsOf(*def, settings, &summary);
    ASSERT_EQ(summary.event, physics::DomainEvent::None);
    settings.orientation = physics::OrientationForm::Quaternion;
    const auto quaternion = rowsOf(*def, settings);
    ASSERT_EQ(angles.size(), quaternion.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < angles.size(); ++i) {
      worst = std::max(worst, (angles[i].state - quaternion[i].state).cwiseAbs().maxCoeff());
      EXPECT_NEAR(angles[i].energy, quaternion[i].energy, 1e-9);
    }
    EXPECT_LT(worst, 1e-9) << (def == &spin ? "free spin" : "M3 tether");
    EXPECT_GT(std::abs(angles.back().state[physics::force_slot::psi]), 2.0 * 3.14159);  // the branch was crossed
  }
}

}  // namespace
}  // namespace hemiroll::game
