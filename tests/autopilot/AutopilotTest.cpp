// engine/autopilot/Autopilot on its own: closed-loop play against the
// engine's model as the plant, a shove included, the refusals it makes in
// play, and bit-for-bit repetition. Its parts have their own files (Goal,
// UprightContact, Reachability, PlannerWorker, LandingSearch, HelixPolicy,
// PlantModel). The plant here is the same PlantModel the planner rolls out,
// driven tick by tick as the servo loop drives it.

#include "engine/autopilot/Autopilot.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <new>
#include <thread>
#include <cstdio>
#include <cstring>

#include "engine/autopilot/UprightContact.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "tests/autopilot/PaperGoal.h"

namespace hemiroll::autopilot {
namespace {

using physics::Vec3;
using test::paperGoal;

struct Played {
  bool success = false;
  double time = 0.0;
  physics::ForceDrivenState final = physics::ForceDrivenState::Zero();
  std::string failure;
  physics::DomainEvent fell = physics::DomainEvent::None;  // how the plant left its domain, if it did
};

// The autopilot against the exact model from `start`, holding the proxy
// from the first tick (it starts on the mass point for an all-zero start).
struct Rig {
  explicit Rig(const AutopilotDef& def, const Goal& goal,
               const physics::ForceDrivenState& start = physics::ForceDrivenState::Zero())
      : pilot(def), plant(def.params, def.coupling, def.dt) {
    plant.reset(start, 0.0);
    in.goal = goal;
    in.engaged = true;
    in.massPosition = Vec3(0.0, 0.0, def.params.radius);
  }
  // What the autopilot sees now (after any change made to the plant).
  void observe() {
    in.time = plant.time();
    in.state = plant.state();
  }
  // A velocity or spin kick: the plant's state changed where it stands.
  void kick(const physics::ForceDrivenState& x) {
    plant.reset(x, plant.time());
    in.state = x;
  }
  Autopilot pilot;
  PlantModel plant;
  AutopilotInput in;
};

// Plays `goal` from `start` for up to `limit` seconds; at `shoveAt` the mass
// point's in-face velocity jumps by `shove` (an impulse on the mass point).
// Leaving the domain (the mass point off the face, tipping over) ends the
// play and fails the test unless `mayFall`.
Played play(const Goal& goal, const physics::ForceDrivenState& start, double limit, double shoveAt = -1.0,
            const physics::Vec2& shove = physics::Vec2::Zero(), const AutopilotDef& def = {}, bool mayFall = false) {
  Rig rig(def, goal, start);
  Autopilot& pilot = rig.pilot;
  PlantModel& plant = rig.plant;
  Played out;
  const auto ticks = static_cast<long long>(limit / def.dt);
  for (long long k = 0; k < ticks; ++k) {
    rig.observe();
    if (shoveAt >= 0.0 && std::abs(rig.in.time - shoveAt) < 0.5 * def.dt) {
      physics::ForceDrivenState x = plant.state();
      x[2] += shove.x();
      x[3] += shove.y();
      rig.kick(x);
    }
    const ProxyCommand c = pilot.act(rig.in);
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

TEST(Autopilot, SolvesThePaperTaskAgainstTheModel) {
  const Played p = play(paperGoal(), physics::ForceDrivenState::Zero(), 60.0);
  EXPECT_TRUE(p.success) << "final u_a " << p.final[7] << ", v_a " << p.final[8];
  EXPECT_LT(p.time, 40.0);  // the paper's best humans: about 40 s
}

// The paper's task with a hold (the paper has none; before the settle
// regulator the landings passed through its bands without staying and
// planning spent its budget by 12.7 s): the bands must hold for 0.1 s in a
// row, and here they must go on holding for 2 s more, every tick: the
// regulated settle comes to rest inside them and stays.
TEST(Autopilot, HoldsThePapersTaskAndStays) {
  Goal goal = paperGoal();
  goal.hold = 0.1;
  const AutopilotDef def;
  Rig rig(def, goal);
  Autopilot& pilot = rig.pilot;
  PlantModel& plant = rig.plant;
  const long long holdTicks = std::llround(goal.hold / def.dt);
  long long inside = 0, leftAfter = 0;
  double held = -1.0;
  for (long long k = 0; k < 60000 && (held < 0.0 || plant.time() < held + 2.0); ++k) {
    rig.observe();
    const ProxyCommand c = pilot.act(rig.in);
    ASSERT_TRUE(pilot.failure().empty()) << pilot.failure();
    ASSERT_EQ(plant.tick(c.position, c.velocity), physics::DomainEvent::None) << "t = " << plant.time();
    const bool in = normalisedError(goal, plant.state()) <= 1.0;
    inside = in ? inside + 1 : 0;
    if (held < 0.0 && inside > holdTicks) held = plant.time();
    if (held >= 0.0 && !in) ++leftAfter;
  }
  ASSERT_GE(held, 0.0) << "not held in 60 s";
  EXPECT_LT(held, 40.0);  // the paper's best humans: about 40 s (measured: 11.9 s)
  EXPECT_EQ(leftAfter, 0);
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

// Two stages from rest upright, each passed once its bands have held for
// its hold, judged here as the level's judge would. The time the second
// stage's hold ends, or -1 (off the face, a planner failure, or the limit).
double playTwoStages(const AutopilotDef& def, const Goal& first, const Goal& second, double limit) {
  Rig rig(def, first);
  PlantModel& plant = rig.plant;
  AutopilotInput& in = rig.in;
  double held = 0.0;
  for (long long k = 0; k < std::llround(limit / def.dt) && rig.pilot.failure().empty(); ++k) {
    rig.observe();
    in.goal = in.stage == 0 ? first : second;
    const ProxyCommand c = rig.pilot.act(in);
    if (plant.tick(c.position, c.velocity) != physics::DomainEvent::None) return -1.0;
    held = normalisedError(in.goal, plant.state()) <= 1.0 ? held + def.dt : 0.0;
    if (held >= in.goal.hold) {
      if (in.stage == 1) return plant.time();
      in.stage = 1;
      held = 0.0;
    }
  }
  return -1.0;
}

// Tutorial 01's two stages on the paper's body: lean 0.1 rad towards +x
// (held 0.5 s), then upright and still (|omega| within 0.03 rad/s, held
// 1 s), no contact point. The glide left the light shell rocking round
// upright and planning spent its budget (7.4 s); the regulator holds the
// rest at the lean asked. The time of the second stage's hold, or -1.
double leanThenStandStill(const AutopilotDef& def, double limit) {
  Goal lean, still;
  for (Goal* g : {&lean, &still})
    for (const int slot : {9, 10}) {
      g->set[static_cast<std::size_t>(slot)] = true;
      g->tolerance[static_cast<std::size_t>(slot)] = 0.03;
    }
  lean.target[9] = -0.1;
  lean.hold = 0.5;
  still.omegaNormSet = true;
  still.omegaNormTolerance = 0.03;
  still.hold = 1.0;
  return playTwoStages(def, lean, still, limit);
}

// Two stages at the paper's bands, each with a hold: reach (3.5, 3.5) cm
// and stay 0.5 s, then stand still with psi within 15 degrees of -2 rad
// and stay 0.5 s. The second stage's lean is held by the regulator (the
// glide: not won in 120 s, AUTOPILOT.md). The time of the last hold, or -1.
double reachThenTurnAndHold(double limit) {
  Goal reach = paperGoal();
  reach.target[7] = reach.target[8] = 0.035;
  reach.hold = 0.5;
  Goal turned;
  const auto band = [&](int slot, double target, double tol) {
    turned.set[static_cast<std::size_t>(slot)] = true;
    turned.target[static_cast<std::size_t>(slot)] = target;
    turned.tolerance[static_cast<std::size_t>(slot)] = tol;
  };
  for (const int slot : {0, 1}) band(slot, 0.0, 0.004);
  for (const int slot : {4, 5, 6}) band(slot, 0.0, 0.01);
  for (const int slot : {9, 10}) band(slot, 0.0, M_PI / 18);
  band(11, -2.0, 15.0 * M_PI / 180.0);
  turned.hold = 0.5;
  return playTwoStages(AutopilotDef(), reach, turned, limit);
}

TEST(Autopilot, HoldsAPsiStageAtThePapersBands) {
  const double t = reachThenTurnAndHold(40.0);
  std::printf("[psi hold] held at %.2f s\n", t);
  EXPECT_GT(t, 0.0);
}

TEST(Autopilot, LeansThenStandsStillOnThePapersBody) {
  AutopilotDef glide;
  glide.regulatedSettle = false;
  const double regulated = leanThenStandStill(AutopilotDef{}, 15.0);
  const double glided = leanThenStandStill(glide, 6.0);
  std::printf("[lean] regulated: held at %.2f s; the glide: %.2f\n", regulated, glided);
  EXPECT_GT(regulated, 0.0);
  EXPECT_LT(regulated, 10.0);
  EXPECT_LT(glided, 0.0);  // the glide, for comparison (not within 6 s)
}

// At rest on the target with only the spin out of its band (what a landing
// that ends spinning leaves: in real time the hand-over spoils the plan,
// and such rests kept watched runs from winning): here the spin is kicked
// by 0.03 rad/s (three times the band) once the paper's task, with a 2 s
// hold, has settled. The brake (SpinBrake.h) takes it out; without it the
// planner searches landing shapes for a landing that is over.
struct Kicked {
  bool won = false;
  double time = 0.0, kickedAt = -1.0;
  long long brakes = 0;  // ticks the law spent braking
};

Kicked kickTheSpinAtRest(bool brake, double limit) {
  AutopilotDef def;
  def.spinBrake = brake;
  Goal goal = paperGoal();
  goal.hold = 4.0;
  Rig rig(def, goal);
  Autopilot& pilot = rig.pilot;
  PlantModel& plant = rig.plant;
  Kicked out;
  double held = 0.0, settledSince = -1.0;
  for (long long k = 0; k < std::llround(limit / def.dt); ++k) {
    rig.observe();
    const double now = rig.in.time;
    const bool settled = pilot.policy().phase() == HelixPhase::Settle && !pilot.policy().braking();
    settledSince = settled ? (settledSince < 0.0 ? now : settledSince) : -1.0;
    if (out.kickedAt < 0.0 && settled && now - settledSince > 3.0) {
      physics::ForceDrivenState x = plant.state();
      x[physics::force_slot::w_z] += 0.03;
      rig.kick(x);
      out.kickedAt = now;
    }
    const ProxyCommand c = pilot.act(rig.in);
    if (pilot.policy().braking()) ++out.brakes;
    EXPECT_EQ(plant.tick(c.position, c.velocity), physics::DomainEvent::None);
    held = out.kickedAt >= 0.0 && normalisedError(goal, plant.state()) <= 1.0 ? held + def.dt : 0.0;
    if (held >= goal.hold) {
      out.won = true;
      break;
    }
  }
  out.time = plant.time();
  return out;
}

TEST(Autopilot, BrakesTheSpinOfARestOnTheTarget) {
  const Kicked braked = kickTheSpinAtRest(true, 40.0);
  std::printf("[brake] kicked at %.2f s: held at %.2f s (%.1f s braking)\n", braked.kickedAt, braked.time,
              braked.brakes * 0.001);
  ASSERT_GE(braked.kickedAt, 0.0);
  EXPECT_TRUE(braked.won);
  EXPECT_GT(braked.brakes, 0);
}

// The same without the brake: the planner searches landing shapes for a
// landing that is over, and the rest keeps spinning (measured: not held in
// 40 s; with the brake held at 20.8 s). Long: its searches cost about
// 20 s of CPU.
TEST(AutopilotHeavy, WithoutTheBrakeARestOnTheTargetKeepsItsSpin) {
  const Kicked braked = kickTheSpinAtRest(true, 40.0);
  const Kicked searched = kickTheSpinAtRest(false, braked.time + 10.0);
  ASSERT_TRUE(braked.won);
  EXPECT_FALSE(searched.won);
  EXPECT_EQ(searched.brakes, 0);
}

// Real time (plannerThread): a decision is applied at the moment it was
// planned for, or counted as dropped when it comes back after it. The
// simulated time is driven by hand, so that which happens does not depend
// on how loaded the machine is.
TEST(Autopilot, CountsRealTimeDecisionsAppliedAndDroppedLate) {
  AutopilotDef def;
  def.plannerThread = true;
  Autopilot pilot(def);
  AutopilotInput in;
  in.goal = paperGoal();
  in.engaged = true;
  in.massPosition = Vec3(0.0, 0.0, def.params.radius);
  const auto actUntil = [&](double time, const auto& done) {
    in.time = time;
    for (int i = 0; i < 10000 && !done(); ++i) {
      pilot.act(in);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  };
  // Posted at 0 for planLead later; the clock held short of that moment
  // while the worker plans, then moved on to it: applied.
  pilot.act(in);
  int calls = 0;
  actUntil(def.planLead - 0.01, [&] { return ++calls > 50; });
  EXPECT_EQ(pilot.realTimePlans().applied, 0u);  // not before its moment
  actUntil(def.planLead, [&] { return pilot.realTimePlans().applied > 0; });
  EXPECT_EQ(pilot.realTimePlans().applied, 1u);
  EXPECT_EQ(pilot.realTimePlans().late, 0u);
  // The next one, posted at planLead, met a clock already far past its moment.
  actUntil(def.planLead + 2.0, [&] { return pilot.realTimePlans().late > 0; });
  EXPECT_EQ(pilot.realTimePlans().applied, 1u);
  EXPECT_EQ(pilot.realTimePlans().late, 1u);
}

}  // namespace
}  // namespace hemiroll::autopilot
