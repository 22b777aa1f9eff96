#include "engine/autopilot/Autopilot.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cmath>

#include "engine/autopilot/LandingSearch.h"
#include "engine/autopilot/PlannerWorker.h"
#include "engine/autopilot/UprightContact.h"
#include "engine/physics/BatchedRk4.h"

namespace hemiroll::autopilot {

using physics::Vec2;
using physics::Vec3;

namespace {

// The zones past zoneCount are not part of the goal (the caller may leave
// old ones there), so Goal gets no defaulted ==.
bool sameGoal(const Goal& a, const Goal& b) {
  if (a.zoneCount != b.zoneCount || !std::equal(a.zones.begin(), a.zones.begin() + a.zoneCount, b.zones.begin()))
    return false;
  return a.target == b.target && a.tolerance == b.tolerance && a.set == b.set && a.omegaNormSet == b.omegaNormSet &&
         a.omegaNormTarget == b.omegaNormTarget && a.omegaNormTolerance == b.omegaNormTolerance && a.hold == b.hold;
}

constexpr double kMaxProxySpeed = 0.25;  // [m/s], see deliverable()

// How long a rollout goes on after the bands first held, to see that the
// hemisphere stays in its domain [s].
constexpr double kAfterSuccess = 1.0;

// Share of the steering offset kept while turning psi on the spot: the
// symmetric helix precesses steadily (about 0.5 rad/s on the paper's model);
// strong steering on top of it tips it into a spin runaway (measured).
constexpr double kTurnSteerShare = 0.3;
constexpr double kTurnAmplitudeShare = 0.4;

// Landing fades the circle at these rates [m/s]; slower landings leave less
// wobble, faster ones less drift. The planner tries them all.
constexpr double kLandRates[] = {0.0015, 0.002, 0.003, 0.004, 0.006, 0.009};
// A landing search waits for psi until a plain landing would end within
// this many psi bands of it: the search turns psi only a little.
constexpr double kRefinePsiBands = 2.0;
// Despin circle radius per rad/s of spin (HelixParams::despinGain) [m s/rad].
constexpr double kDespinGains[] = {0.0, 0.01};

}  // namespace

Autopilot::Autopilot(const AutopilotDef& def)
    : def_(def),
      constants_(def.params),
      policy_(constants_, def.helix, def.dt),
      work_(policy_),
      model_(def.params, def.coupling, def.dt),
      domain_(def.params) {
  def_.budget = std::clamp(def_.budget, 0.25, 4.0);
  def_.helix.stiffen = def_.handStiffens ? stiffeningFor(def_.params, def_.coupling, 1.0) : 0.0;
  policy_.params().stiffen = def_.helix.stiffen;
  if (def_.regulatedSettle) policy_.setSettleGain(settleGainFor(def_.params, def_.coupling, def_.dt));
  policy_.enableRegulator(def_.handStiffens);
  work_ = policy_;
  stats_.decisionWall.reserve(4096);
  if (def_.plannerThread)
    worker_ = std::make_unique<PlannerWorker>([this](const PlanJob& j) { return plan(j); }, def_.plannerNice);
}

Autopilot::~Autopilot() = default;

double stiffeningFor(const physics::HemisphereParams& params, const physics::CouplingDef& coupling, double share) {
  // Upright, a still proxy holds the mass point on top only while the
  // spring's pull beats the point's weight over the face's lever: k_r R >
  // m_p g. The paper's body stands at the edge (m_p g / (k_r R) = 0.98) and
  // the law was shaped there. A weaker spring lets the mass point fall off
  // within a second (measured: 7 of 7 generated tasks with the ratio at
  // 1.16-1.43, none below 1); a stiffer one holds the hemisphere so firmly
  // that the helix hardly drifts (0.1-0.4 mm/s at the ratio 0.34, against
  // 13 mm/s on the paper's body). So the hand makes every coupling act as
  // one at the ratio kLawRatio: it stiffens a weak one and softens a stiff
  // one (measured on the shipped levels: tutorial 05 in 14.6 s instead of
  // 90.1 s, tutorial 04 in 4.6 s instead of 19.3 s). A coupling too weak even
  // at full force is made up for the share the engagement ramp still holds
  // back, too (at most kMostStiffening times); one that holds at full force
  // rides the ramp out unaided (making up the ramp there too made the
  // tutorials slower: tutorial 04 22.1 s, tutorial 05 16.6 s).
  constexpr double kLawRatio = 0.95, kMostStiffening = 20.0;
  const double ratio = params.pointMass * params.gravity / (coupling.stiffness * params.radius);
  if (ratio <= 1.0) return ratio / kLawRatio - 1.0;
  return std::min(ratio / (kLawRatio * std::max(share, 1e-3)) - 1.0, kMostStiffening);
}

Vec3 Autopilot::deliverable(const Vec3& wanted, const Vec3& last, long long ticks) const {
  // A hand moves the stylus smoothly: at most kMaxProxySpeed, far below the
  // device's velocity guard (2 m/s), so that a jump of the plan (a new stage,
  // a new steering angle) never trips it.
  Vec3 step = insideWorkspace(wanted) - last;
  const double most = kMaxProxySpeed * static_cast<double>(ticks) * def_.dt;
  if (step.norm() > most) step *= most / step.norm();
  return last + step;
}

Vec3 Autopilot::insideWorkspace(const Vec3& p) const {
  // 2 mm inside the device's sphere: the device stops the stylus there anyway,
  // and the planner's rollouts must see the pose the device will deliver.
  const Vec3 d = p - def_.workspace.centre;
  const double most = def_.workspace.radius - 0.002;
  return d.norm() > most ? Vec3(def_.workspace.centre + d * (most / d.norm())) : p;
}

double Autopilot::uprightError(const Vec2& upright) const {
  if (!planGoal_.contactSet()) return 0.0;
  Vec2 d = Vec2::Zero();
  if (planGoal_.set[7]) d.x() = planGoal_.target[7] - upright.x();
  if (planGoal_.set[8]) d.y() = planGoal_.target[8] - upright.y();
  return d.norm();
}

ProxyCommand Autopilot::act(const AutopilotInput& input) {
  if (!started_) {
    lastProxy_ = input.massPosition;
    firstActTime_ = input.time;
    started_ = true;
  }
  checkPlanningBudget(input.time);
  ProxyCommand out;
  out.position = lastProxy_;
  if (!failure_.empty()) return out;  // hold still; the game ends the trial
  if ((input.stage != stage_ || !sameGoal(input.goal, given_)) && !takeGoal(input)) return out;
  if (!input.engaged) {
    // Take hold: bring the proxy onto the mass point, as a player does.
    policy_.startAt(input.massPosition);
    policyTime_ = input.time;
    out.position = insideWorkspace(input.massPosition);
    out.velocity = input.massVelocity;
    lastProxy_ = out.position;
    return out;
  }
  policy_.params().stiffen = def_.handStiffens ? stiffeningFor(def_.params, def_.coupling, input.forceShare) : 0.0;
  policy_.enableRegulator(def_.handStiffens);
  if (given_.set[11] && !turningPsi_ && normalisedError(goal_, input.state) <= 1.0) startTurningPsi(input.time);
  if (def_.plannerThread)
    exchangeWithWorker(input);
  else if (input.time >= nextDecision_ - 1e-9) {
    apply(plan(job(input)));
    nextDecision_ = input.time + def_.decisionPeriod;
  }
  return stepPolicy(input);
}

void Autopilot::checkPlanningBudget(double time) {
  if (!failure_.empty() || (def_.planningRolloutSeconds <= 0.0 && def_.planningRolloutSecondsPerSimulatedSecond <= 0.0))
    return;
  const double simulated = time - firstActTime_;
  const double allowed = def_.budget * (def_.planningRolloutSeconds +
                                        def_.planningRolloutSecondsPerSimulatedSecond * std::max(0.0, simulated));
  if (plannedSeconds() <= allowed) return;
  char why[300];
  std::snprintf(why, sizeof why,
                "planning has rolled out %.0f s by %.1f s of simulated time, more than its budget (%g x (%g s + "
                "%g s per simulated second)): the task looks beyond it",
                plannedSeconds(), simulated, def_.budget, def_.planningRolloutSeconds,
                def_.planningRolloutSecondsPerSimulatedSecond);
  failure_ = why;
}

bool Autopilot::takeGoal(const AutopilotInput& input) {
  ++generation_;  // a plan still running for the old goal is dropped
  stage_ = input.stage;
  given_ = input.goal;
  goal_ = input.goal;
  // psi in two steps: first the rest of the stage (psi turns freely while
  // the helix travels, and a landing can move it only a little), then,
  // from rest on the target, a helix that precesses on the spot until a
  // landing ends with psi inside its band too.
  turningPsi_ = false;
  goal_.set[11] = false;
  policy_.setGoal(goal_);
  // A stage with a psi band that is only passed through (no hold) glides to
  // its lean: faster (the generated tasks' second stages: regulated, 1-7 s
  // slower on 9 of 10 seeds). One that must stay there (a hold) needs the
  // regulator (two such tasks at the paper's bands: won in 15 and 27 s,
  // gliding not in 120 s).
  policy_.regulateLean(!given_.set[11] || given_.hold > 0.0);
  failure_ = unreachableReason(goal_, def_.params, def_.workspace);
  if (!failure_.empty()) return false;
  if (goal_.contactSet())
    policy_.travel();
  else
    policy_.settleNow();
  resetPlanner_ = true;
  return true;
}

void Autopilot::startTurningPsi(double time) {
  turningPsi_ = true;
  goal_ = given_;
  policy_.setGoal(goal_);
  policy_.travel();
  policy_.params().amplitude = kTurnAmplitudeShare * def_.helix.amplitude;
  policy_.params().steerLimit = kTurnSteerShare * def_.helix.steerLimit;
  ++generation_;
  holdSteer_ = true;  // keep the gentle circle for a while before steering again
  nextDecision_ = time;
}

void Autopilot::exchangeWithWorker(const AutopilotInput& input) {
  Decision ready;
  if (!pending_ && worker_->take(ready)) {
    if (ready.generation == generation_) {
      pending_ = ready;
      refineNext_ = refineNext_ || ready.wantsRefinement;
    } else {
      stale_.fetch_add(1, std::memory_order_relaxed);
    }
  }
  if (pending_ && input.time >= pending_->applyAt - 0.5 * def_.dt) {
    // Applied at the moment it was planned for; one that came too late
    // (the plan took longer than its lead) is dropped.
    if (input.time - pending_->applyAt <= 0.005) {
      apply(*pending_);
      applied_.fetch_add(1, std::memory_order_relaxed);
    } else {
      late_.fetch_add(1, std::memory_order_relaxed);
    }
    pending_.reset();
  }
  if (!pending_ && input.time >= nextDecision_ - 1e-9) {
    PlanJob next = job(input);
    next.lead = refineNext_ ? def_.refineLead : def_.planLead;
    next.mayRefine = refineNext_;
    if (worker_->post(next)) {
      nextDecision_ = input.time + def_.decisionPeriod;
      refineNext_ = false;
    }
  }
}

ProxyCommand Autopilot::stepPolicy(const AutopilotInput& input) {
  // One policy step per servo tick since the last call: headless that is
  // one, a real-time caller at a lower rate gets the same motion.
  const long long steps = std::clamp(std::llround((input.time - policyTime_) / def_.dt), 1LL, 100LL);
  policyTime_ = input.time;
  Vec3 proxy;
  for (long long i = 0; i < steps; ++i) proxy = policy_.proxyFor(input.state);
  ProxyCommand out;
  out.position = deliverable(proxy, lastProxy_, steps);
  // Over the ticks this call stands for, so that a device that extrapolates
  // with it (real-time hand-over) follows the same path.
  out.velocity = (out.position - lastProxy_) / (static_cast<double>(steps) * def_.dt);
  lastProxy_ = out.position;
  return out;
}

Autopilot::PlanJob Autopilot::job(const AutopilotInput& input) {
  PlanJob j(policy_);
  j.input = input;
  j.goal = goal_;
  j.turning = turningPsi_;
  j.lastProxy = lastProxy_;
  j.generation = generation_;
  j.resetTimers = resetPlanner_;
  j.holdSteer = holdSteer_;
  resetPlanner_ = holdSteer_ = false;
  return j;
}

void Autopilot::apply(const Decision& d) {
  if (d.steer) {
    policy_.params().steerAngle = d.steerAngle;
    policy_.params().amplitude = d.amplitude;
  }
  if (d.action == Decision::Action::Land && policy_.phase() == HelixPhase::Travel)
    policy_.land(d.landRate, d.despin, d.shape);
  else if (d.action == Decision::Action::Travel)
    policy_.travel();
  else if (d.action == Decision::Action::Reshape && policy_.phase() != HelixPhase::Travel)
    policy_.reshape(d.shape);
  else if (d.action == Decision::Action::Brake && policy_.phase() == HelixPhase::Settle)
    startBrake(policy_, d.brake);
}

Autopilot::Decision Autopilot::plan(const PlanJob& job) {
  const auto start = std::chrono::steady_clock::now();
  AutopilotInput input = job.input;
  work_ = job.policy;
  planGoal_ = job.goal;
  planTurning_ = job.turning;
  planLastProxy_ = job.lastProxy;
  planMayRefine_ = job.mayRefine;
  planDeadline_.reset();
  if (job.lead > 0.0) {
    // Ready before its moment, with a margin for the hand-over.
    planDeadline_ = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(0.8 * job.lead));
    predict(input, job.lead);
  }
  decision_ = Decision{};
  decision_.generation = job.generation;
  decision_.applyAt = input.time;
  if (job.resetTimers) lastSteer_ = -1e9;
  if (job.holdSteer) lastSteer_ = input.time;
  ++stats_.decisions;
  if (work_.braking()) {
    // The brake runs its course (seconds); the settle after it is verified.
  } else if (work_.phase() == HelixPhase::Travel) {
    if (input.time - lastSteer_ >= def_.steerPeriod - 1e-9) steer(input);
    tryLanding(input);
  } else {
    verifyLanding(input);
  }
  stats_.decisionWall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return decision_;
}

void Autopilot::predict(AutopilotInput& input, double lead) {
  // The running law for `lead` seconds through the model, from the job's
  // state: where the trial will be when the decision is applied.
  model_.reset(input.state, input.time);
  const long long ticks = std::llround(lead / def_.dt);
  for (long long k = 0; k < ticks; ++k) {
    const Vec3 proxy = deliverable(work_.proxyFor(model_.state()), planLastProxy_);
    const Vec3 velocity = (proxy - planLastProxy_) / def_.dt;
    planLastProxy_ = proxy;
    plannedTicks_.fetch_add(1, std::memory_order_relaxed);
    if (model_.tick(proxy, velocity) != physics::DomainEvent::None) break;
  }
  input.time = model_.time();
  input.state = model_.state();
}

namespace {

// Lanes for n rollouts: a group no wider than needed (a lane stepped for
// nothing costs as much as one in use).
int laneWidthFor(std::size_t n) {
  for (int width : {1, 2, 4, 8})
    if (static_cast<std::size_t>(width) >= n && physics::laneWidthSupported(width)) return width;
  return physics::bestLaneWidth();
}

}  // namespace

// One rollout's progress: what the loop of a single rollout keeps.
struct Autopilot::RolloutLane {
  Outcome o;
  physics::ForceDrivenState x;  // the lane's state after the last tick
  Vec3 last;
  long long ticks = 0, k = 0, inside = 0, meanCount = 0;
  double meanError = 0.0;
  bool done = false;
};

std::vector<Autopilot::Outcome> Autopilot::rollouts(std::vector<HelixPolicy> policies, const AutopilotInput& input,
                                                    double horizon, bool judge) {
  const std::size_t n = policies.size();
  physics::ForceDrivenBatch batch(def_.coupling.method, laneWidthFor(n));
  std::vector<RolloutLane> lanes = startRollouts(batch, n, input, horizon);
  const long long holdTicks = std::llround(planGoal_.hold / def_.dt);
  for (long long tick = 0; batch.activeCount() > 0; ++tick) {
    holdRolloutProxies(batch, lanes, policies);
    batch.step(0.0, def_.dt);
    for (std::size_t i = 0; i < n; ++i) {
      if (lanes[i].done) continue;
      lanes[i].x = batch.state(static_cast<int>(i));
      if (judgeRolloutTick(lanes[i], tick, judge, holdTicks)) {
        lanes[i].done = true;
        batch.retire(static_cast<int>(i));
      }
    }
  }
  return rolloutOutcomes(lanes);
}

std::vector<Autopilot::RolloutLane> Autopilot::startRollouts(physics::ForceDrivenBatch& batch, std::size_t n,
                                                             const AutopilotInput& input, double horizon) {
  std::vector<RolloutLane> lanes(n);
  // A start outside the domain: PlantModel's stepper reports it at the first tick.
  const bool startsOutside = domain_.domainEvent(input.time, input.state) != physics::DomainEvent::None;
  for (std::size_t i = 0; i < n; ++i) {
    batch.add(def_.params, def_.coupling, input.state);
    lanes[i].x = input.state;
    lanes[i].last = planLastProxy_;
    lanes[i].ticks = std::llround(horizon / def_.dt);
    lanes[i].done = lanes[i].ticks <= 0;
    if (startsOutside && !lanes[i].done) {
      lanes[i].o.event = true;
      lanes[i].done = true;
    }
    if (lanes[i].done) batch.retire(static_cast<int>(i));
  }
  return lanes;
}

void Autopilot::holdRolloutProxies(physics::ForceDrivenBatch& batch, std::vector<RolloutLane>& lanes,
                                   std::vector<HelixPolicy>& policies) const {
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    if (lanes[i].done) continue;
    physics::ProxyPose pose;
    pose.position = deliverable(policies[i].proxyFor(lanes[i].x), lanes[i].last);
    pose.velocity = (pose.position - lanes[i].last) / def_.dt;
    lanes[i].last = pose.position;
    batch.holdProxy(static_cast<int>(i), pose);
  }
}

bool Autopilot::judgeRolloutTick(RolloutLane& lane, long long tick, bool judge, long long holdTicks) const {
  Outcome& o = lane.o;
  if (domain_.domainEvent(0.0, lane.x) != physics::DomainEvent::None || inForbiddenZone(planGoal_, lane.x)) {
    o.event = true;
    o.success = false;
    return true;
  }
  lane.k = tick + 1;
  if (!o.success) {
    if (judge) scoreBands(lane, tick, holdTicks);
    else scoreDrift(lane, tick);
  }
  return lane.k >= lane.ticks;
}

// The second half of the horizon: c_up rides a loop per turn of the helix,
// so its mean, not its last value, says where the drift goes.
void Autopilot::scoreDrift(RolloutLane& lane, long long tick) const {
  if (2 * tick < lane.ticks) return;
  const UprightContact up = uprightContact(constants_, lane.x);
  lane.meanError += uprightError(up.point);
  ++lane.meanCount;
  lane.o.excess = std::max(lane.o.excess, std::max(0.0, std::abs(lane.x[6]) - 1.2) + std::max(0.0, up.tilt - 0.9));
}

void Autopilot::scoreBands(RolloutLane& lane, long long tick, long long holdTicks) const {
  Outcome& o = lane.o;
  const physics::ForceDrivenState& x = lane.x;
  const double e = normalisedError(planGoal_, x);
  const double soft = squaredError(planGoal_, x);
  if (soft < o.softCost) {
    o.softCost = soft;
    o.psiError = planGoal_.set[11]
                     ? std::abs(std::remainder(x[11] - planGoal_.target[11], 2.0 * M_PI)) / planGoal_.tolerance[11]
                     : 0.0;
  }
  lane.inside = e <= 1.0 ? lane.inside + 1 : 0;
  if (lane.inside > holdTicks) {
    // Held: but a plan that swings through the bands and tips over a moment
    // later hands the next stage a wreck, so it must also stay in the domain
    // for kAfterSuccess more.
    o.success = true;
    o.time = static_cast<double>(tick + 1) * def_.dt;
    lane.ticks = std::min(lane.ticks, tick + 1 + std::llround(kAfterSuccess / def_.dt));
  }
}

std::vector<Autopilot::Outcome> Autopilot::rolloutOutcomes(std::vector<RolloutLane>& lanes) {
  std::vector<Outcome> out;
  out.reserve(lanes.size());
  for (RolloutLane& lane : lanes) {
    stats_.rolloutSeconds += static_cast<double>(lane.k) * def_.dt;
    plannedTicks_.fetch_add(lane.k, std::memory_order_relaxed);
    lane.o.meanUprightError = lane.meanCount > 0 ? lane.meanError / static_cast<double>(lane.meanCount) : 1e30;
    out.push_back(lane.o);
  }
  return out;
}

Autopilot::Outcome Autopilot::rollout(const HelixPolicy& policy, const AutopilotInput& input, double horizon,
                                      bool judge) {
  return rollouts({policy}, input, horizon, judge).front();
}

void Autopilot::steer(const AutopilotInput& input) {
  lastSteer_ = input.time;
  if (!planGoal_.contactSet()) return;
  const int each = std::max(1, static_cast<int>(std::lround(def_.budget)));
  const double baseAngle = work_.params().steerAngle;
  const double baseAmplitude = work_.params().amplitude;
  double bestAngle = baseAngle, bestAmplitude = baseAmplitude, bestCost = 1e30;
  // Turning psi on the spot keeps the full circle: it is what precesses.
  const std::array<double, 3> scales = {1.0, 0.7, 1.3};
  std::vector<HelixPolicy> candidates;
  for (int si = 0; si < (planTurning_ ? 1 : 3); ++si) {
    const double scale = scales[static_cast<std::size_t>(si)];
    for (int i = -each; i <= each; ++i) {
      HelixPolicy candidate = work_;
      candidate.params().steerAngle = baseAngle + i * def_.steerStep / each;
      candidate.params().amplitude = planTurning_ ? baseAmplitude
                                                 : std::clamp(baseAmplitude * scale, 0.3 * def_.helix.amplitude, def_.helix.amplitude);
      candidates.push_back(candidate);
    }
  }
  const std::vector<Outcome> outcomes = rollouts(candidates, input, def_.steerHorizon, false);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    // A candidate that tips over or throws the mass point off is never
    // kept; fast spin and deep tilts are what lead there, so they cost.
    const Outcome& o = outcomes[c];
    const double cost = o.event ? 1e30 : o.meanUprightError + 0.01 * o.excess;
    if (cost < bestCost) {
      bestCost = cost;
      bestAngle = candidates[c].params().steerAngle;
      bestAmplitude = candidates[c].params().amplitude;
    }
  }
  work_.params().steerAngle = std::remainder(bestAngle, 2.0 * M_PI);
  work_.params().amplitude = bestAmplitude;
  decision_.steer = true;
  decision_.steerAngle = work_.params().steerAngle;
  decision_.amplitude = bestAmplitude;
}

bool Autopilot::tryLanding(const AutopilotInput& input) {
  const Vec2 upright = uprightContact(constants_, input.state).point;
  if (uprightError(upright) > def_.landConsider) return false;
  // A landing search that found nothing is not repeated at once: the helix
  // needs a few tenths of a second to bring a different state round.
  if (input.time < nextLandingTry_) return false;
  nextLandingTry_ = input.time + def_.landRetryPeriod;
  const double horizon = def_.landHorizon * std::min(2.0, def_.budget);
  Outcome best;
  double bestRate = 0.0, bestDespin = 0.0, psiNearest = 1e30;
  for (const double despin : kDespinGains) {
    std::vector<HelixPolicy> candidates;
    for (const double rate : kLandRates) {
      candidates.push_back(work_);
      candidates.back().land(rate, despin);
    }
    const std::vector<Outcome> outcomes = rollouts(candidates, input, horizon, true);
    for (std::size_t c = 0; c < outcomes.size(); ++c) {
      const Outcome& o = outcomes[c];
      psiNearest = std::min(psiNearest, o.psiError);
      if (o.success && (!best.success || o.time < best.time)) {
        best = o;
        bestRate = kLandRates[c];
        bestDespin = despin;
      }
    }
    if (best.success) break;  // the plainest landing that works
  }
  if (best.success) {
    work_.land(bestRate, bestDespin);
    decision_.action = Decision::Action::Land;
    decision_.landRate = bestRate;
    decision_.despin = bestDespin;
    return true;
  }
  // The refinement reshapes the landing by millimetres: it can take spin
  // out, but it turns psi only a little, so with a band on psi it waits for
  // the helix to bring psi round (plain landings ending within 3 bands).
  // It is for stages that end at rest (a band on omega); a stage the
  // hemisphere only passes through needs none, and a shape tuned to swing
  // through its band would hand the next stage a wild start.
  const bool atRest = planGoal_.set[4] || planGoal_.set[5] || planGoal_.set[6] || planGoal_.omegaNormSet;
  // Landing from a shallow tilt leaves less to undo: the hovering helix
  // wobbles between about 0.2 and 0.6 rad, so the search waits for the low.
  const double tilt = uprightContact(constants_, input.state).tilt;
  if (!atRest || uprightError(upright) > def_.refineConsider || input.time < nextRefinement_ || psiNearest > kRefinePsiBands ||
      tilt > def_.refineTilt)
    return false;
  if (!mayRefine()) return false;
  nextRefinement_ = input.time + def_.refineRetryPeriod;
  return refineLanding(input, horizon, false);
}

bool Autopilot::refineLanding(const AutopilotInput& input, double horizon, bool reshape) {
  // Successive searches vary the fade rate and the first spread, so that a
  // hover that defeats one setting meets another, and a hover that has
  // defeated searches before gets longer ones (up to 4x the rounds).
  constexpr double kRateScale[] = {1.0, 0.5, 2.0};
  constexpr double kSpreadScale[] = {1.0, 1.5, 0.75};
  // Turning psi on the spot, a search mostly fails because psi has not
  // come round yet, not because the hover defeats it, so searches there are
  // not lengthened (longer ones found no more landings on the generated
  // tasks and cost psi tasks up to 0.3 s of CPU per simulated second).
  const double escalation = planTurning_ ? 1.0 : 1.0 + static_cast<double>(std::min<std::uint64_t>(refinements_, 3));
  const std::uint64_t attempt = ++refinements_;
  LandingSearchDef search;
  search.population = std::max(8, static_cast<int>(std::lround(32 * def_.budget)));
  search.elites = std::max(3, search.population / 5);
  search.rounds = std::max(2, static_cast<int>(std::lround(8 * def_.budget * escalation)));
  search.spread = def_.refineSpread * kSpreadScale[(attempt / 3) % 3];
  search.seed = def_.seed ^ (0x5bd1e995ULL * attempt);
  if (planDeadline_)
    search.outOfTime = [deadline = *planDeadline_] { return std::chrono::steady_clock::now() > deadline; };
  const double landRate = def_.refineLandRate * kRateScale[attempt % 3];
  // The shapes of a batch are rolled out together, one per lane.
  search.batch = physics::bestLaneWidth();
  const ScoreShapes score = [&](const std::vector<LandingShape>& shapes) {
    std::vector<HelixPolicy> candidates(shapes.size(), work_);
    for (std::size_t c = 0; c < shapes.size(); ++c) {
      if (reshape)
        candidates[c].reshape(shapes[c]);
      else
        candidates[c].land(landRate, 0.0, shapes[c]);
    }
    std::vector<ShapeScore> scores;
    // Scored by the smallest sum of squared normalised errors on the way.
    for (const Outcome& o : rollouts(std::move(candidates), input, horizon, true))
      scores.push_back(ShapeScore{o.success, o.event ? 1e30 : o.softCost});
    return scores;
  };
  const std::optional<LandingShape> shape = searchLandingShape(search, score);
  if (!shape) return false;
  if (reshape) {
    work_.reshape(*shape);
    decision_.action = Decision::Action::Reshape;
    decision_.shape = *shape;
    return true;
  }
  work_.land(landRate, 0.0, *shape);
  decision_.action = Decision::Action::Land;
  decision_.landRate = landRate;
  decision_.despin = 0.0;
  decision_.shape = *shape;
  return true;
}

bool Autopilot::mayRefine() {
  if (planMayRefine_) return true;
  decision_.wantsRefinement = true;
  return false;
}

void Autopilot::verifyLanding(const AutopilotInput& input) {
  // Every few decisions is enough: the landing takes seconds.
  if (stats_.decisions % 3 != 0) return;
  const Outcome o = rollout(work_, input, def_.landHorizon, true);
  if (o.success) return;
  const Vec2 upright = uprightContact(constants_, input.state).point;
  if (uprightError(upright) > def_.landConsider || o.event) {
    work_.travel();
    decision_.action = Decision::Action::Travel;
    lastSteer_ = -1e9;
    return;
  }
  // Still near: the landing drifted from its plan (a small shove, or real
  // time's hand-over). At rest with only the spin left, the brake takes it
  // out; else search a new shape for the rest of the landing, from here.
  const bool atRest = planGoal_.set[4] || planGoal_.set[5] || planGoal_.set[6] || planGoal_.omegaNormSet;
  if (atRest && tryBrake(input)) return;
  if (atRest && input.time >= nextRefinement_ && mayRefine()) {
    nextRefinement_ = input.time + def_.refineRetryPeriod;
    refineLanding(input, def_.landHorizon, true);
  }
}

bool Autopilot::tryBrake(const AutopilotInput& input) {
  using namespace physics::force_slot;
  if (!def_.spinBrake || !def_.handStiffens || work_.phase() != HelixPhase::Settle) return false;
  // The spin the rest keeps is w_z only near rest (SpinBrake.h); the
  // regulator's own gate (HelixPolicy.cpp) says what near is.
  const double tilt = uprightContact(constants_, input.state).tilt;
  if (tilt > 0.1 || std::hypot(input.state[w_x], input.state[w_y]) > 0.2) return false;
  const double band = planGoal_.set[w_z] ? planGoal_.tolerance[w_z] : planGoal_.omegaNormSet ? planGoal_.omegaNormTolerance : 0.0;
  const double spin = input.state[w_z] - (planGoal_.set[w_z] ? planGoal_.target[w_z] : 0.0);
  if (band <= 0.0 || std::abs(spin) < 0.5 * band) return false;
  if (!brakeTable_) {
    const SpinBrakeDef def;
    brakeTable_ = spinBrakeTableFor(def_.params, def_.coupling, work_.params(), work_.settleGain(), def_.dt, def);
    // Its rollouts count towards planning's budget like any other.
    plannedTicks_.fetch_add(std::llround((brakeTable_->rows + 1) * (def.lock + def.settle) / def_.dt),
                            std::memory_order_relaxed);
  }
  const SpinBrakeCommand command = spinBrakeFor(*brakeTable_, spin);
  if (!command.valid) return false;
  HelixPolicy braked = work_;
  startBrake(braked, command);
  if (!rollout(braked, input, command.lock + def_.landHorizon, true).success) return false;
  work_ = braked;
  decision_.action = Decision::Action::Brake;
  decision_.brake = command;
  return true;
}

}  // namespace hemiroll::autopilot
