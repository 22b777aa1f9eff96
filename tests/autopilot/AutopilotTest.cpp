// engine/autopilot on its own: the invariant it steers by (c_up), the
// up-front refusals, and closed-loop play against the engine's model as the
// plant, a shove included. The plant here is the same PlantModel the planner
// rolls out, driven tick by tick as the servo loop drives it.

#include "engine/autopilot/Autopilot.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <new>
#include <thread>
#include <cstring>

#include "engine/autopilot/LandingSearch.h"
#include "engine/autopilot/PlannerWorker.h"
#include "engine/autopilot/UprightContact.h"
#include "engine/physics/ForceDrivenSystem.h"

namespace hemiroll::autopilot {
namespace {

using physics::Vec3;

// The paper's task (levels/paper_reaching.lua) as a Goal.
Goal paperGoal() {
  Goal g;
  const auto band = [&](int slot, double target, double tol) {
    g.set[static_cast<std::size_t>(slot)] = true;
    g.target[static_cast<std::size_t>(slot)] = target;
    g.tolerance[static_cast<std::size_t>(slot)] = tol;
  };
  for (int slot : {0, 1}) band(slot, 0.0, 0.004);
  for (int slot : {2, 3}) band(slot, 0.0, 0.004);
  for (int slot : {4, 5, 6}) band(slot, 0.0, 0.01);
  band(7, -0.04, 0.004);
  band(8, -0.04, 0.004);
  for (int slot : {9, 10}) band(slot, 0.0, M_PI / 18);
  return g;
}

struct Played {
  bool success = false;
  double time = 0.0;
  physics::ForceDrivenState final = physics::ForceDrivenState::Zero();
  std::string failure;
  physics::DomainEvent fell = physics::DomainEvent::None;  // how the plant left its domain, if it did
};

// Plays `goal` from `start` for up to `limit` seconds; at `shoveAt` the mass
// point's in-face velocity jumps by `shove` (an impulse on the mass point).
// Leaving the domain (the mass point off the face, tipping over) ends the
// play and fails the test unless `mayFall`.
Played play(const Goal& goal, const physics::ForceDrivenState& start, double limit, double shoveAt = -1.0,
            const physics::Vec2& shove = physics::Vec2::Zero(), const AutopilotDef& def = {}, bool mayFall = false) {
  Autopilot pilot(def);
  PlantModel plant(def.params, def.coupling, def.dt);
  plant.reset(start, 0.0);
  Played out;
  AutopilotInput in;
  in.goal = goal;
  in.engaged = true;  // the proxy starts on the mass point (all-zero start)
  in.massPosition = Vec3(0.0, 0.0, def.params.radius);
  const auto ticks = static_cast<long long>(limit / def.dt);
  for (long long k = 0; k < ticks; ++k) {
    in.time = plant.time();
    in.state = plant.state();
    if (shoveAt >= 0.0 && std::abs(in.time - shoveAt) < 0.5 * def.dt) {
      physics::ForceDrivenState x = plant.state();
      x[2] += shove.x();
      x[3] += shove.y();
      plant.reset(x, plant.time());
      in.state = x;
    }
    const ProxyCommand c = pilot.act(in);
    if (!pilot.failure().empty()) {
      out.failure = pilot.failure();
      break;
    }
    out.fell = plant.tick(c.position, c.velocity);
    if (out.fell != physics::DomainEvent::None) {
      EXPECT_TRUE(mayFall) << "left the domain at t = " << plant.time();
      break;
    }
    if (normalisedError(goal, plant.state()) <= 1.0) {
      out.success = true;
      break;
    }
  }
  out.time = plant.time();
  out.final = plant.state();
  return out;
}

TEST(UprightContact, AStraightRollKeepsIt) {
  // Proxy held 1 cm off along x: the hemisphere rolls straight about y by
  // 0.24 rad and the contact moves 9.4 mm, but c_up stays at the start. On a
  // great circle the identity is exact; what is left is RK4's error.
  AutopilotDef def;
  PlantModel plant(def.params, def.coupling, def.dt);
  plant.reset(physics::ForceDrivenState::Zero(), 0.0);
  for (int k = 0; k < 3000; ++k) plant.tick(Vec3(0.01, 0.0, def.params.radius), Vec3::Zero());
  const UprightContact up = uprightContact(plant.constants(), plant.state());
  EXPECT_GT(plant.state()[physics::force_slot::u_a], 0.009);
  EXPECT_GT(up.tilt, 0.2);
  EXPECT_LT(up.point.norm(), 1e-9);
}

TEST(UprightContact, UprightItIsTheContactPoint) {
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x[physics::force_slot::u_a] = 0.03;
  x[physics::force_slot::v_a] = -0.02;
  x[physics::force_slot::psi] = 1.0;
  const UprightContact up = uprightContact(physics::ModelConstants(physics::HemisphereParams{}), x);
  EXPECT_DOUBLE_EQ(up.point.x(), 0.03);
  EXPECT_DOUBLE_EQ(up.point.y(), -0.02);
  EXPECT_DOUBLE_EQ(up.tilt, 0.0);
}

TEST(Goal, ErrorIsTheWorstBandAndPsiWraps) {
  Goal g;
  g.set[11] = true;
  g.target[11] = M_PI - 0.05;
  g.tolerance[11] = 0.1;
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  x[11] = -M_PI + 0.02;  // 0.07 from the target across the seam
  EXPECT_NEAR(normalisedError(g, x), 0.7, 1e-12);
  g.omegaNormSet = true;
  g.omegaNormTolerance = 0.01;
  x[6] = 0.02;
  EXPECT_NEAR(normalisedError(g, x), 2.0, 1e-12);
}

TEST(Goal, ZonesKnowTheirEdge) {
  Zone circle;
  circle.centre = {0.01, 0.0};
  circle.radius = 0.002;
  EXPECT_NEAR(circle.clearance(physics::Vec2(0.0, 0.0)), 0.008, 1e-15);
  EXPECT_NEAR(circle.clearance(physics::Vec2(0.01, 0.001)), -0.001, 1e-15);
  Zone box;
  box.circle = false;
  box.min = {0.0, 0.0};
  box.max = {0.01, 0.02};
  EXPECT_NEAR(box.clearance(physics::Vec2(0.013, 0.024)), 0.005, 1e-15);  // 3-4-5 from the corner
  EXPECT_NEAR(box.clearance(physics::Vec2(0.002, 0.01)), -0.002, 1e-15);  // nearest side 2 mm away
  Goal g;
  g.zones[0] = circle;
  g.zoneCount = 1;
  physics::ForceDrivenState x = physics::ForceDrivenState::Zero();
  EXPECT_FALSE(inForbiddenZone(g, x));
  x[physics::force_slot::u_a] = 0.0095;
  EXPECT_TRUE(inForbiddenZone(g, x));
}

TEST(Reachability, RefusesWhatCanNeverBeReached) {
  const physics::HemisphereParams params;
  Workspace ws;
  Goal far = paperGoal();
  far.target[7] = 0.2;  // 20 cm: beyond a 10 cm device
  EXPECT_NE(unreachableReason(far, params, ws).find("beyond its reach"), std::string::npos);

  Goal rim;
  rim.set[9] = true;
  rim.target[9] = 1.7;
  rim.tolerance[9] = 0.05;
  EXPECT_NE(unreachableReason(rim, params, ws).find("past the rim"), std::string::npos);

  Goal offFace;
  offFace.set[0] = true;
  offFace.target[0] = 0.05;
  offFace.tolerance[0] = 0.005;
  EXPECT_NE(unreachableReason(offFace, params, ws).find("off the face"), std::string::npos);

  // At rest tilted by 0.5 rad needs p ~ R sin 0.5 = 19 mm; p held within 4 mm.
  Goal contradictory = paperGoal();
  contradictory.target[9] = 0.5;
  contradictory.tolerance[9] = 0.05;
  EXPECT_NE(unreachableReason(contradictory, params, ws).find("rest at a tilt"), std::string::npos);

  EXPECT_EQ(unreachableReason(paperGoal(), params, ws), "");
}

TEST(Autopilot, SolvesThePaperTaskAgainstTheModel) {
  const Played p = play(paperGoal(), physics::ForceDrivenState::Zero(), 60.0);
  EXPECT_TRUE(p.success) << "final u_a " << p.final[7] << ", v_a " << p.final[8];
  EXPECT_LT(p.time, 40.0);  // the paper's best humans: about 40 s
}

TEST(Autopilot, RecoversFromAShove) {
  // 3 s in, mid-helix, the mass point is knocked sideways at 5 cm/s (a 0.05
  // N s impulse on 1 kg): the plan made before no longer holds, and the
  // planner, rolling out from the measured state, must still get there.
  const Played p = play(paperGoal(), physics::ForceDrivenState::Zero(), 120.0, 3.0, physics::Vec2(0.05, 0.0));
  EXPECT_TRUE(p.success) << "final u_a " << p.final[7] << ", v_a " << p.final[8];
  // The shove mattered: the unshoved run ends elsewhere and at another time.
  const Played calm = play(paperGoal(), physics::ForceDrivenState::Zero(), 120.0);
  EXPECT_NE(p.time, calm.time);
}

TEST(Autopilot, TheHandMakesEveryCouplingActAsOneAtTheLawsRatio) {
  physics::HemisphereParams paper;  // m_p g / (k_r R) = 0.981 at k_r = 250
  physics::CouplingDef coupling;
  const double ratio = paper.pointMass * paper.gravity / (coupling.stiffness * paper.radius);
  EXPECT_NEAR(stiffeningFor(paper, coupling, 1.0), ratio / 0.95 - 1.0, 1e-15);
  EXPECT_EQ(stiffeningFor(paper, coupling, 0.3), stiffeningFor(paper, coupling, 1.0));  // it holds: the ramp is ridden out
  coupling.stiffness = 500.0;  // twice as stiff: softened by about half
  EXPECT_NEAR(1.0 + stiffeningFor(paper, coupling, 1.0), ratio / 2.0 / 0.95, 1e-12);
  coupling.stiffness = 175.0;  // ratio 1.40: too weak to hold the mass point on top
  const double full = stiffeningFor(paper, coupling, 1.0);
  EXPECT_NEAR((1.0 + full) * coupling.stiffness, paper.pointMass * paper.gravity / (0.95 * paper.radius), 1e-9);
  EXPECT_GT(stiffeningFor(paper, coupling, 0.5), full);      // half the force: the hand makes up more
  EXPECT_EQ(stiffeningFor(paper, coupling, 0.0), 20.0);      // and at most 20 times
}

TEST(Autopilot, BalancesACouplingTooWeakToHoldTheMassPointOnTop) {
  // The paper's body on M2 at 175 N/m (a generated task that fell off the
  // face within a second before the hand stiffened the coupling).
  AutopilotDef def;
  def.coupling.method = physics::ForceMethod::M2;
  def.coupling.stiffness = 175.0;
  def.coupling.damping = 7.0;
  def.coupling.alpha = 1.0;
  ASSERT_GT(stiffeningFor(def.params, def.coupling, 1.0), 0.0);
  const Played p = play(paperGoal(), physics::ForceDrivenState::Zero(), 120.0, -1.0, physics::Vec2::Zero(), def);
  EXPECT_TRUE(p.success) << p.failure << " t = " << p.time;
  EXPECT_EQ(p.fell, physics::DomainEvent::None);
  // The fall it avoids: the same law with the hand holding the coupling as
  // the level has it throws the mass point off the face.
  def.handStiffens = false;
  const Played unaided =
      play(paperGoal(), physics::ForceDrivenState::Zero(), 120.0, -1.0, physics::Vec2::Zero(), def, true);
  EXPECT_FALSE(unaided.success);
  EXPECT_NE(unaided.fell, physics::DomainEvent::None) << "t = " << unaided.time << " " << unaided.failure;
}

TEST(Autopilot, GivesUpAtOnceOnAnUnreachableTarget) {
  Goal far = paperGoal();
  far.target[7] = far.target[8] = 0.3;
  const Played p = play(far, physics::ForceDrivenState::Zero(), 5.0);
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.failure.find("beyond its reach"), std::string::npos);
  EXPECT_LT(p.time, 0.01);
}

// Planning has a budget per trial tied to the simulated time (issue 33):
// spent, the autopilot gives up with the reason, as on a task it can neither
// win nor refuse, instead of planning for as long as the level lasts. Here
// the budget is made tiny (50 s rolled out, nothing per simulated second) so
// that the paper's task, which needs about 1300 s, meets it. The budget is
// counted in simulated seconds, not CPU, so the give-up is the same on any
// machine: two runs end at the same tick with the same words.
TEST(Autopilot, GivesUpWhenPlanningHasSpentItsBudget) {
  AutopilotDef def;
  def.planningRolloutSeconds = 50.0;
  def.planningRolloutSecondsPerSimulatedSecond = 0.0;
  const Played p = play(paperGoal(), physics::ForceDrivenState::Zero(), 20.0, -1.0, physics::Vec2::Zero(), def);
  EXPECT_FALSE(p.success);
  EXPECT_NE(p.failure.find("planning has rolled out"), std::string::npos) << p.failure;
  EXPECT_NE(p.failure.find("more than its budget (1 x (50 s + 0 s per simulated second))"), std::string::npos)
      << p.failure;
  EXPECT_LT(p.time, 20.0);  // gave up, did not play on to the limit
  const Played again = play(paperGoal(), physics::ForceDrivenState::Zero(), 20.0, -1.0, physics::Vec2::Zero(), def);
  EXPECT_EQ(again.time, p.time);
  EXPECT_EQ(again.failure, p.failure);
}

TEST(Autopilot, SameInputsSameProxyBitForBit) {
  const Played a = play(paperGoal(), physics::ForceDrivenState::Zero(), 60.0);
  const Played b = play(paperGoal(), physics::ForceDrivenState::Zero(), 60.0);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(std::memcmp(a.final.data(), b.final.data(), sizeof(double) * 12), 0);
}

}  // namespace
}  // namespace hemiroll::autopilot

namespace hemiroll::autopilot {
namespace {

TEST(PlannerWorker, RunsOneJobAtATimeAndHandsBackItsDecision) {
  std::atomic<bool> release{false};
  PlannerWorker worker([&](const Autopilot::PlanJob& job) {
    while (!release.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    Autopilot::Decision d;
    d.generation = job.generation;
    d.steer = true;
    d.steerAngle = job.input.time;
    return d;
  });
  const physics::ModelConstants constants{physics::HemisphereParams{}};
  HelixPolicy policy(constants, HelixParams{}, 0.001);
  Autopilot::PlanJob job(policy);
  job.generation = 7;
  job.input.time = 1.25;
  ASSERT_TRUE(worker.post(job));
  EXPECT_FALSE(worker.post(job));  // busy: refused, not queued
  Autopilot::Decision d;
  EXPECT_FALSE(worker.take(d));    // not done yet: take does not wait
  release = true;
  for (int i = 0; i < 5000 && !worker.take(d); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(d.generation, 7u);
  EXPECT_EQ(d.steerAngle, 1.25);
  EXPECT_TRUE(worker.post(job));   // free again once taken
}

}  // namespace
}  // namespace hemiroll::autopilot

namespace hemiroll::autopilot {
namespace {

// A bowl in the 16 knot coordinates with its floor at 1 mm on every one:
// success within 0.2 mm of it (the spread starts at 2 mm).
ShapeScore bowl(const LandingShape& s) {
  double cost = 0.0, worst = 0.0;
  for (const physics::Vec2& k : s.knots)
    for (int c = 0; c < 2; ++c) {
      const double d = k[c] - 0.001;
      cost += d * d;
      worst = std::max(worst, std::abs(d));
    }
  return ShapeScore{worst < 2e-4, cost};
}

TEST(LandingSearch, FindsAShapeNearAnOptimumAndRepeatsItsDrawsPerSeed) {
  const ScoreShape score = bowl;
  LandingSearchDef def;
  def.rounds = 40;
  def.seed = 3;
  const std::optional<LandingShape> a = searchLandingShape(def, score);
  ASSERT_TRUE(a.has_value());
  EXPECT_NEAR(a->knots[0].x(), 0.001, 2e-4);
  const std::optional<LandingShape> b = searchLandingShape(def, score);
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(a->knots, b->knots);  // same seed, same draws
  def.rounds = 1;
  EXPECT_FALSE(searchLandingShape(def, score).has_value());  // one round from zero cannot get there
}

TEST(LandingSearch, OutOfTimeEndsTheSearchBeforeTheNextShape) {
  // The same bowl, solvable in 40 rounds; the clock runs out after five
  // shapes: a sixth is never scored, and nothing is returned.
  int scored = 0, asked = 0;
  const auto score = [&](const LandingShape& s) {
    ++scored;
    double cost = 0.0;
    for (const physics::Vec2& k : s.knots) cost += (k - physics::Vec2(0.001, 0.001)).squaredNorm();
    return ShapeScore{cost < 1e-12, cost};
  };
  LandingSearchDef def;
  def.rounds = 40;
  def.outOfTime = [&] { return ++asked > 5; };
  EXPECT_FALSE(searchLandingShape(def, score).has_value());
  EXPECT_EQ(scored, 5);
  EXPECT_EQ(asked, 6);
}

TEST(LandingSearch, ScoringInBatchesFindsTheSameShapeAndAsksTheClockPerBatch) {
  // The bowl, scored a batch at a time: the shape found is the
  // one-at-a-time search's, bit for bit, for any batch size (the draws and
  // the order of judging do not change); the clock is asked before each
  // batch.
  const ScoreShape one = bowl;
  LandingSearchDef def;
  def.rounds = 40;
  def.seed = 3;
  const std::optional<LandingShape> alone = searchLandingShape(def, one);
  ASSERT_TRUE(alone.has_value());
  for (int batch : {2, 5, 8, 32}) {
    def.batch = batch;
    std::size_t largest = 0;
    const std::optional<LandingShape> batched = searchLandingShape(def, [&](const std::vector<LandingShape>& shapes) {
      largest = std::max(largest, shapes.size());
      std::vector<ShapeScore> scores;
      for (const LandingShape& s : shapes) scores.push_back(one(s));
      return scores;
    });
    ASSERT_TRUE(batched.has_value()) << "batch " << batch;
    EXPECT_EQ(batched->knots, alone->knots) << "batch " << batch;
    EXPECT_EQ(largest, static_cast<std::size_t>(batch));
  }
  int asked = 0;
  std::size_t scored = 0;
  def.batch = 8;
  def.outOfTime = [&] { return ++asked > 2; };
  EXPECT_FALSE(searchLandingShape(def, [&](const std::vector<LandingShape>& shapes) {
                 scored += shapes.size();
                 return std::vector<ShapeScore>(shapes.size());
               }).has_value());
  EXPECT_EQ(scored, 16u);  // two batches of 8, then the clock ran out
  EXPECT_EQ(asked, 3);
}

TEST(LandingShape, ADefaultShapeIsNoOffsetAtAll) {
  // Eigen vectors are not zeroed by value-initialisation; a plain landing
  // (no shape) must add nothing. Built in memory filled with garbage first,
  // so that a shape that forgot to set its knots shows it.
  alignas(LandingShape) unsigned char memory[sizeof(LandingShape)];
  std::memset(memory, 0x5a, sizeof memory);
  const LandingShape* s = new (memory) LandingShape;  // default-initialised, as `= {}` and members are
  for (double t = 0.0; t < LandingShape::kKnots * s->spacing; t += 0.05) EXPECT_EQ(s->at(t), physics::Vec2::Zero()) << t;
  s->~LandingShape();
}

TEST(LandingShape, IsLinearBetweenKnotsAndZeroAfterTheLast) {
  LandingShape s;
  s.knots[0] = physics::Vec2(0.002, 0.0);
  s.knots[1] = physics::Vec2(0.0, 0.004);
  EXPECT_NEAR(s.at(0.2).x(), 0.001, 1e-15);  // halfway from knot 0 to knot 1 (0.4 s apart)
  EXPECT_NEAR(s.at(0.2).y(), 0.002, 1e-15);
  EXPECT_EQ(s.at(-0.1), physics::Vec2::Zero());
  EXPECT_EQ(s.at(LandingShape::kKnots * s.spacing + 0.1), physics::Vec2::Zero());
}

}  // namespace
}  // namespace hemiroll::autopilot
