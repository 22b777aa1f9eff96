#include "engine/autopilot/Autopilot.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/autopilot/UprightContact.h"

namespace hemiroll::autopilot {

using physics::Vec2;
using physics::Vec3;

namespace {

bool sameGoal(const Goal& a, const Goal& b) {
  return a.target == b.target && a.tolerance == b.tolerance && a.set == b.set && a.omegaNormSet == b.omegaNormSet &&
         a.omegaNormTarget == b.omegaNormTarget && a.omegaNormTolerance == b.omegaNormTolerance && a.hold == b.hold;
}

// Landing fades the circle at these rates [m/s]; slower landings leave less
// wobble, faster ones less drift. The planner tries them all.
constexpr double kMaxProxySpeed = 0.25;  // [m/s]

constexpr double kLandRates[] = {0.0015, 0.002, 0.003, 0.004, 0.006, 0.009};
// Despin circle radius per rad/s of spin (HelixParams::despinGain) [m s/rad].
constexpr double kDespinGains[] = {0.0, 0.01};

}  // namespace

Autopilot::Autopilot(const AutopilotDef& def)
    : def_(def),
      constants_(def.params),
      policy_(constants_, def.helix, def.dt),
      model_(def.params, def.coupling, def.dt) {
  def_.budget = std::clamp(def_.budget, 0.25, 4.0);
  stats_.decisionWall.reserve(4096);
}

Vec3 Autopilot::deliverable(const Vec3& wanted, const Vec3& last) const {
  // A hand moves the stylus smoothly: at most kMaxProxySpeed, far below the
  // device's velocity guard (2 m/s), so that a jump of the plan (a new stage,
  // a new steering angle) never trips it.
  Vec3 step = insideWorkspace(wanted) - last;
  const double most = kMaxProxySpeed * def_.dt;
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
  if (!goal_.contactSet()) return 0.0;
  Vec2 d = Vec2::Zero();
  if (goal_.set[7]) d.x() = goal_.target[7] - upright.x();
  if (goal_.set[8]) d.y() = goal_.target[8] - upright.y();
  return d.norm();
}

ProxyCommand Autopilot::act(const AutopilotInput& input) {
  ProxyCommand out;
  if (!started_) {
    lastProxy_ = input.massPosition;
    started_ = true;
  }
  if (!failure_.empty()) {  // hold still; the game ends the trial
    out.position = lastProxy_;
    return out;
  }
  if (input.stage != stage_ || !sameGoal(input.goal, goal_)) {
    stage_ = input.stage;
    goal_ = input.goal;
    policy_.setGoal(goal_);
    failure_ = unreachableReason(goal_, def_.params, def_.workspace);
    if (!failure_.empty()) {
      out.position = lastProxy_;
      return out;
    }
    if (goal_.contactSet()) policy_.travel();
    else policy_.settleNow();
    lastSteer_ = -1e9;
  }
  if (!input.engaged) {
    // Take hold: bring the proxy onto the mass point, as a player does.
    policy_.startAt(input.massPosition);
    policyTime_ = input.time;
    out.position = insideWorkspace(input.massPosition);
    out.velocity = input.massVelocity;
    lastProxy_ = out.position;
    return out;
  }
  if (input.time >= nextDecision_ - 1e-9) {
    plan(input);
    nextDecision_ = input.time + def_.decisionPeriod;
  }
  // One policy step per servo tick since the last call: headless that is
  // one, a real-time caller at a lower rate gets the same motion.
  const long long steps = std::clamp(std::llround((input.time - policyTime_) / def_.dt), 1LL, 100LL);
  policyTime_ = input.time;
  Vec3 proxy;
  for (long long i = 0; i < steps; ++i) proxy = policy_.proxyFor(input.state);
  out.position = deliverable(proxy, lastProxy_);
  out.velocity = (out.position - lastProxy_) / def_.dt;
  lastProxy_ = out.position;
  return out;
}

void Autopilot::plan(const AutopilotInput& input) {
  const auto start = std::chrono::steady_clock::now();
  ++stats_.decisions;
  if (policy_.phase() == HelixPhase::Travel) {
    if (input.time - lastSteer_ >= def_.steerPeriod - 1e-9) steer(input);
    tryLanding(input);
  } else {
    verifyLanding(input);
  }
  stats_.decisionWall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

Autopilot::Outcome Autopilot::rollout(HelixPolicy policy, const AutopilotInput& input, double horizon, bool judge) {
  ++stats_.rollouts;
  model_.reset(input.state, input.time);
  Vec3 last = lastProxy_;
  policy.startAt(last);  // keeps the glide continuous from the real proxy
  Outcome o;
  const long long ticks = std::llround(horizon / def_.dt);
  const long long holdTicks = std::llround(goal_.hold / def_.dt);
  long long inside = 0;
  long long k = 0;
  double meanError = 0.0;
  long long meanCount = 0;
  for (; k < ticks; ++k) {
    const Vec3 proxy = deliverable(policy.proxyFor(model_.state()), last);
    const Vec3 velocity = (proxy - last) / def_.dt;
    last = proxy;
    if (model_.tick(proxy, velocity) != physics::DomainEvent::None) {
      o.event = true;
      break;
    }
    if (!judge) {
      // The second half of the horizon: c_up rides a loop per turn of the
      // helix, so its mean, not its last value, says where the drift goes.
      if (2 * k >= ticks) {
        const UprightContact up = uprightContact(constants_, model_.state());
        meanError += uprightError(up.point);
        ++meanCount;
        o.excess = std::max(o.excess, std::max(0.0, std::abs(model_.state()[6]) - 1.2) + std::max(0.0, up.tilt - 0.9));
      }
      continue;
    }
    const double e = normalisedError(goal_, model_.state());
    o.bestError = std::min(o.bestError, e);
    inside = e <= 1.0 ? inside + 1 : 0;
    if (inside > holdTicks) {
      o.success = true;
      o.time = static_cast<double>(k + 1) * def_.dt;
      break;
    }
  }
  stats_.rolloutSeconds += static_cast<double>(k) * def_.dt;
  o.meanUprightError = meanCount > 0 ? meanError / static_cast<double>(meanCount) : 1e30;
  o.upright = uprightContact(constants_, model_.state()).point;
  return o;
}

void Autopilot::steer(const AutopilotInput& input) {
  lastSteer_ = input.time;
  if (!goal_.contactSet()) return;
  const int each = std::max(1, static_cast<int>(std::lround(def_.budget)));
  const double baseAngle = policy_.params().steerAngle;
  const double baseAmplitude = policy_.params().amplitude;
  double bestAngle = baseAngle, bestAmplitude = baseAmplitude, bestCost = 1e30;
  for (const double scale : {1.0, 0.7, 1.3}) {
    for (int i = -each; i <= each; ++i) {
      HelixPolicy candidate = policy_;
      candidate.params().steerAngle = baseAngle + i * def_.steerStep / each;
      candidate.params().amplitude = std::clamp(baseAmplitude * scale, 0.3 * def_.helix.amplitude, def_.helix.amplitude);
      const Outcome o = rollout(candidate, input, def_.steerHorizon, false);
      // A candidate that tips over or throws the mass point off is never
      // kept; fast spin and deep tilts are what lead there, so they cost.
      const double cost = o.event ? 1e30 : o.meanUprightError + 0.01 * o.excess;
      if (cost < bestCost) {
        bestCost = cost;
        bestAngle = candidate.params().steerAngle;
        bestAmplitude = candidate.params().amplitude;
      }
    }
  }
  policy_.params().steerAngle = std::remainder(bestAngle, 2.0 * M_PI);
  policy_.params().amplitude = bestAmplitude;
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
  double bestRate = 0.0, bestDespin = 0.0;
  for (const double despin : kDespinGains) {
    for (const double rate : kLandRates) {
      HelixPolicy candidate = policy_;
      candidate.land(rate, despin);
      const Outcome o = rollout(candidate, input, horizon, true);
      if (o.success && (!best.success || o.time < best.time)) {
        best = o;
        bestRate = rate;
        bestDespin = despin;
      }
    }
    if (best.success) break;  // the plainest landing that works
  }
  if (!best.success) return false;
  policy_.land(bestRate, bestDespin);
  stats_.landedAt = input.time;
  return true;
}

void Autopilot::verifyLanding(const AutopilotInput& input) {
  // Every few decisions is enough: the landing takes seconds.
  if (stats_.decisions % 3 != 0) return;
  const Outcome o = rollout(policy_, input, def_.landHorizon, true);
  if (o.success) return;
  const Vec2 upright = uprightContact(constants_, input.state).point;
  if (uprightError(upright) > def_.landConsider || o.event) {
    policy_.travel();
    lastSteer_ = -1e9;
  }
}

}  // namespace hemiroll::autopilot
