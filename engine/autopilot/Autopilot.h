#pragma once
// engine/autopilot: plays a reaching task the way a player does, by moving
// the haptic proxy, from the observation alone.
//
// Owns: the helix feedback law (HelixPolicy), the planner that picks its
// parameters and the moment to land by rolling copies of it forward through
// the engine's own model (PlantModel), and the up-front check of targets it
// can never reach (Reachability).
// Must not know: Lua, levels, devices, the judge, the game. It gets a Goal
// and a state, and gives a proxy pose; what the proxy does to the model
// (coupling, ramp, safety, judging) is the game's own. Its one thread of its
// own (PlannerWorker, real time only) shares nothing with the servo tick.
//
// How it decides (docs/AUTOPILOT.md): every tick it runs HelixPolicy; every
// `decisionPeriod` it plans, by rolling copies of the policy out:
//   travelling: every `steerPeriod` it tries steering angles and circle
//     radii over `steerHorizon` and keeps the pair that brings c_up closest
//     to the target; once c_up is within `landConsider` of it, it rolls out
//     landing now at each fade rate for up to `landHorizon` and lands with
//     the first that the model says ends inside every band (for the stage's
//     hold time, and stays in the domain a second more); if none does and
//     c_up is within `refineConsider`, it searches a landing shape
//     (LandingSearch). That rollout is the plan: it closes the loop on the
//     measured state at every decision.
//   landing or settling: it rolls the current plan out again; if the model
//     no longer predicts success, it travels again when c_up has left the
//     landing reach (a shove), else it searches a new shape for the rest of
//     the landing.
//   psi: a stage with a psi band is played without it first, then psi is
//     turned on the spot by a gentle helix from rest.
// The candidates of one decision (steering's angles and radii, a row of
// landing rates, a batch of landing shapes) are rolled out together, one
// per SIMD lane (physics::ForceDrivenBatch); each lane has the bits of a
// rollout through PlantModel alone, so the plans do not depend on it.
// Headless plans run inside act(): same inputs, same outputs, bit for bit.

#include <atomic>
#include <cstdint>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/autopilot/Goal.h"
#include "engine/autopilot/HelixPolicy.h"
#include "engine/autopilot/PlantModel.h"
#include "engine/autopilot/SpinBrake.h"
#include "engine/autopilot/Reachability.h"

namespace hemiroll::physics {
class ForceDrivenBatch;
}

namespace hemiroll::autopilot {

struct AutopilotDef {
  physics::HemisphereParams params;
  physics::CouplingDef coupling;
  double dt = 0.001;      // servo period [s]
  Workspace workspace;    // where the proxy may go (scene)
  HelixParams helix;      // the feedback law's starting parameters
  // Planning effort [-]: scales the number of candidates and the landing
  // horizon (1 = the defaults below; 0.25 .. 4).
  double budget = 1.0;
  double decisionPeriod = 0.1;  // [s] between plans
  double steerPeriod = 0.5;     // [s] between steering updates
  double steerHorizon = 2.0;    // [s]
  double steerStep = 0.4;       // [rad] between steering candidates
  double landHorizon = 10.0;    // [s]
  double landConsider = 0.01;   // [m] c_up this close to the target: try landing
  double landRetryPeriod = 0.3; // [s] between landing searches
  // When no plain landing works and c_up is this close: search the landing
  // shape (HelixPolicy.h) by cross-entropy, at this fade rate, starting with
  // this spread of the knots.
  double refineConsider = 0.003;  // [m]
  double refineLandRate = 0.003;  // [m/s]
  double refineSpread = 0.002;    // [m]
  double refineRetryPeriod = 1.0; // [s] between refinements
  double refineTilt = 0.35;       // [rad] refine only below this tilt
  std::uint64_t seed = 0;         // the refinement's draws (same seed, same plan)
  // Plan on a thread of its own (real-time play): act() then never waits
  // for a plan; it posts the state and applies each decision when it is
  // ready, a few ticks later. Off (headless): plans run inside act(), so a
  // run is deterministic.
  bool plannerThread = false;
  double planLead = 0.3;  // [s] how far ahead a real-time plan is made (PlanJob::lead)
  // A landing-shape search costs tenths of a second to seconds, more than
  // planLead: in real time a plan that wants one asks for it, and the next
  // plan is made this far ahead and given 80 % of it to search.
  double refineLead = 1.5;  // [s]
  // The planning thread's nice value (Linux). 19 yields to everything, the
  // servo thread under the normal scheduler included, where a device that
  // renders force is stopped by a tick 20 ms late. But then any other
  // program at the normal priority starves the planner (a nice-19 thread
  // gets 15/1039 of a core it shares with one): watched in the window with
  // one core kept busy, a quarter to half of its plans came back late and
  // were dropped, and the hemisphere hovered on its target (AUTOPILOT.md,
  // "Real time"). So where its own hand renders no force (watching, whose
  // late ticks are ridden out) the companion plans at 0.
  int plannerNice = 19;
  // The autopilot holds the proxy itself, so its hand may stiffen or soften
  // the coupling (HelixParams::stiffen, stiffeningFor). Off where another
  // hand holds the proxy and the plan is only a guide or a hint.
  bool handStiffens = true;
  // Settle with the regulator (SettleRegulator.h): it comes to rest and
  // stays. Off: the glide of before, which passes through tight bands.
  bool regulatedSettle = true;
  // Take a rest's spin out with the brake (SpinBrake.h) when a landing has
  // come to rest on its target with only the spin out of its band, instead
  // of searching landing shapes for what is left of the landing.
  bool spinBrake = true;
  // Planning's work per trial (issue 33): at most budget x
  // (planningRolloutSeconds + planningRolloutSecondsPerSimulatedSecond x the
  // simulated time since the first act), counted in seconds the planner's
  // model simulated (rollouts and predictions), not on a clock, so that a
  // headless trial ends the same on any machine however loaded. Past it the
  // autopilot gives up with the reason: a task it can neither win nor refuse
  // up front (contradictory stages, a rest the bands rule out) planned at
  // about 2 s of CPU per simulated second, 8 minutes for a 240 s level. The
  // model simulates about 3400 s per second of CPU (measured, AUTOPILOT.md),
  // so the defaults are about 6 s + 0.9 s of CPU per simulated second; won
  // tasks use up to 660 s per simulated second (full orientation). 0 and 0:
  // no budget.
  double planningRolloutSeconds = 20000.0;
  double planningRolloutSecondsPerSimulatedSecond = 3000.0;
};

struct AutopilotInput {
  double time = 0.0;                                                     // [s]
  physics::ForceDrivenState state = physics::ForceDrivenState::Zero();  // the measured 12-state
  physics::Vec3 massPosition = physics::Vec3::Zero();                    // scene [m]
  physics::Vec3 massVelocity = physics::Vec3::Zero();                    // scene [m/s]
  bool engaged = false;  // the coupling holds the mass point
  double forceShare = 1.0;  // the share of the coupling's force acting (the engagement ramp) [-]
  Goal goal;             // the current stage's bands
  int stage = 0;
};

struct ProxyCommand {
  physics::Vec3 position = physics::Vec3::Zero();  // scene [m]
  physics::Vec3 velocity = physics::Vec3::Zero();  // scene [m/s]
};

// Real-time plans (AutopilotDef::plannerThread) and what became of them:
// applied at their moment, or dropped because they came back after it (the
// planning thread starved or the plan too long for its lead) or were made
// for a goal since replaced. Any thread may read them.
struct RealTimePlanCounts {
  std::uint64_t applied = 0, late = 0, stale = 0;
};

// What the planner did, for the issue note and the benchmark.
struct PlannerStats {
  long long decisions = 0;
  double rolloutSeconds = 0.0;        // simulated time rolled out [s]
  std::vector<double> decisionWall;   // wall time of each decision [s]
};

class PlannerWorker;

// How much the hand stiffens the coupling for this body (HelixParams::stiffen)
// when `share` of the coupling's force acts (the engagement ramp): 0 where
// the spring alone holds the mass point on top.
double stiffeningFor(const physics::HemisphereParams& params, const physics::CouplingDef& coupling, double share);

class Autopilot {
 public:
  explicit Autopilot(const AutopilotDef& def);
  ~Autopilot();
  Autopilot(const Autopilot&) = delete;
  Autopilot& operator=(const Autopilot&) = delete;

  ProxyCommand act(const AutopilotInput& input);

  // Time the planner's model has simulated so far [s] (any thread may read it).
  double plannedSeconds() const {
    return def_.dt * static_cast<double>(plannedTicks_.load(std::memory_order_relaxed));
  }
  // Non-empty once the autopilot has given up ("the target ... is beyond ...").
  const std::string& failure() const { return failure_; }
  // Read it only while no plan is running (headless, or after the trial).
  const PlannerStats& stats() const { return stats_; }
  RealTimePlanCounts realTimePlans() const {
    return {applied_.load(std::memory_order_relaxed), late_.load(std::memory_order_relaxed),
            stale_.load(std::memory_order_relaxed)};
  }
  // The running law as of the last act (act's thread).
  const HelixPolicy& policy() const { return policy_; }
  // Whether the autopilot's own hand holds the proxy from now on
  // (AutopilotDef::handStiffens; act's thread).
  void setHandStiffens(bool on) { def_.handStiffens = on; }

  // What one plan decides, applied to the running policy.
  struct Decision {
    enum class Action { None, Land, Travel, Reshape, Brake };
    bool steer = false;
    double steerAngle = 0.0, amplitude = 0.0;
    Action action = Action::None;
    double landRate = 0.0, despin = 0.0;
    LandingShape shape;
    SpinBrakeCommand brake;        // Action::Brake
    std::uint64_t generation = 0;  // the goal it was made for
    double applyAt = 0.0;          // the time of the state it was made for [s]
    // Real time: a landing-shape search is due but this plan had no time
    // for it; the next plan gets refineLead.
    bool wantsRefinement = false;
  };
  // Everything a plan reads, copied when it is posted.
  struct PlanJob {
    explicit PlanJob(const HelixPolicy& p) : policy(p) {}
    AutopilotInput input;
    HelixPolicy policy;
    Goal goal;
    bool turning = false;
    physics::Vec3 lastProxy = physics::Vec3::Zero();
    std::uint64_t generation = 0;
    bool resetTimers = false, holdSteer = false;
    // Plan for the state `lead` seconds ahead, predicted by running the
    // policy through the model, so that the decision can be applied at that
    // very moment (real time: a plan takes time; 0 headless).
    double lead = 0.0;
    // Whether a landing-shape search may run in this plan (headless
    // always; real time only in a plan made refineLead ahead).
    bool mayRefine = true;
  };

 private:
  struct Outcome {
    bool success = false;
    bool event = false;
    double time = 0.0;       // when the bands were first held [s after start]
    double meanUprightError = 1e30;  // |c_up - target| averaged over the second half [m]
    double excess = 0.0;             // largest spin above 1.2 rad/s plus tilt above 0.9 rad
    double softCost = 1e30;          // smallest sum of squared normalised errors on the way
    double psiError = 1e30;          // |psi - target| / tolerance there (0 without a psi band)
  };

  Decision plan(const PlanJob& job);
  // act's steps: give up once planning has spent its budget; take a new
  // stage's goal (false: refused, failure_ says why); start turning psi on
  // the spot; trade plans with the worker (real time); the policy's ticks.
  void checkPlanningBudget(double time);
  bool takeGoal(const AutopilotInput& input);
  void startTurningPsi(double time);
  void exchangeWithWorker(const AutopilotInput& input);
  ProxyCommand stepPolicy(const AutopilotInput& input);
  void predict(AutopilotInput& input, double lead);
  PlanJob job(const AutopilotInput& input);
  void apply(const Decision& decision);
  void steer(const AutopilotInput& input);
  bool tryLanding(const AutopilotInput& input);
  // reshape: replace the running landing's shape from now (landing or
  // settling already) instead of starting a landing.
  bool refineLanding(const AutopilotInput& input, double horizon, bool reshape);
  void verifyLanding(const AutopilotInput& input);
  // At rest on the target with only the spin out of its band: the brake
  // that takes it out, if a rollout says the bands then hold.
  bool tryBrake(const AutopilotInput& input);
  // False (and the decision asks for time) when this plan may not search.
  bool mayRefine();
  // Each policy rolled out through the model from input, all together in
  // SIMD lanes (physics::ForceDrivenBatch): each outcome is the one a rollout
  // of that policy alone through model_ gives, bit for bit.
  std::vector<Outcome> rollouts(std::vector<HelixPolicy> policies, const AutopilotInput& input, double horizon,
                                bool judge);
  // rollouts' steps: the lanes started; each lane's proxy for the next tick;
  // a lane's state judged after a tick (true: the lane is finished), by the
  // drift of its upright contact (steering) or by the goal's bands (judge);
  // the outcomes collected.
  struct RolloutLane;
  std::vector<RolloutLane> startRollouts(physics::ForceDrivenBatch& batch, std::size_t n, const AutopilotInput& input,
                                         double horizon);
  void holdRolloutProxies(physics::ForceDrivenBatch& batch, std::vector<RolloutLane>& lanes,
                          std::vector<HelixPolicy>& policies) const;
  bool judgeRolloutTick(RolloutLane& lane, long long tick, bool judge, long long holdTicks) const;
  void scoreDrift(RolloutLane& lane, long long tick) const;
  void scoreBands(RolloutLane& lane, long long tick, long long holdTicks) const;
  std::vector<Outcome> rolloutOutcomes(std::vector<RolloutLane>& lanes);
  Outcome rollout(const HelixPolicy& policy, const AutopilotInput& input, double horizon, bool judge);
  double uprightError(const physics::Vec2& upright) const;
  physics::Vec3 insideWorkspace(const physics::Vec3& p) const;
  // `wanted` moved no further from `last` than the proxy speed limit allows in
  // `ticks` servo ticks, and kept inside the workspace.
  physics::Vec3 deliverable(const physics::Vec3& wanted, const physics::Vec3& last, long long ticks = 1) const;

  AutopilotDef def_;
  physics::ModelConstants constants_;
  HelixPolicy policy_;  // the running law (act's thread)

  // The planner's side: touched only by plan() (act's thread headless, the
  // worker's in real time).
  HelixPolicy work_;    // the copy a plan works on
  Goal planGoal_;
  bool planTurning_ = false;
  physics::Vec3 planLastProxy_ = physics::Vec3::Zero();
  Decision decision_;
  bool planMayRefine_ = true;
  // Real time: when the plan must be ready; none headless.
  std::optional<std::chrono::steady_clock::time_point> planDeadline_;
  PlantModel model_;
  physics::ForceDrivenSystem domain_;  // the model's domain check, for the lanes
  Goal given_;  // the stage's goal as given
  Goal goal_;   // the one pursued now (given_ without psi until the rest holds)
  bool turningPsi_ = false;
  int stage_ = -1;
  bool started_ = false;
  double nextDecision_ = 0.0;  // [s]
  double policyTime_ = 0.0;    // time the policy has been run up to [s]
  double lastSteer_ = -1e9;
  double nextLandingTry_ = 0.0;  // [s]
  std::uint64_t refinements_ = 0;
  std::optional<SpinBrakeTable> brakeTable_;  // the planner's: made at the first brake considered
  double nextRefinement_ = 0.0;  // [s]
  physics::Vec3 lastProxy_ = physics::Vec3::Zero();
  std::string failure_;
  PlannerStats stats_;
  // Model ticks the planner simulated, added by whichever thread plans, read by act's.
  std::atomic<std::int64_t> plannedTicks_{0};
  double firstActTime_ = 0.0;
  std::uint64_t generation_ = 0;
  bool resetPlanner_ = false, holdSteer_ = false;
  bool refineNext_ = false;  // act's side: the next real-time plan gets refineLead
  std::unique_ptr<PlannerWorker> worker_;
  std::optional<Decision> pending_;  // a real-time decision waiting for its moment
  std::atomic<std::uint64_t> applied_{0}, late_{0}, stale_{0};  // RealTimePlanCounts
};

}  // namespace hemiroll::autopilot
