#include "engine/haptics/ServoLoop.h"

#include <cstdio>

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/physics/Energy.h"
#include "engine/physics/StateKinematics.h"

namespace hemiroll::haptics {

using physics::ForceDrivenState;

namespace {

Triple toTriple(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

std::string ServoLoop::couplingProblem(const physics::CouplingDef& c, const DeviceSpec& spec) {
  std::string problem = physics::validateCoupling(c);
  if (!problem.empty()) return problem;
  const double stiffest = c.stiffness * (c.method == physics::ForceMethod::M3 ? std::max(1.0, c.alpha) : 1.0);
  if (!c.visualOnly && spec.hasForceOutput && stiffest > spec.maxStiffness) {
    // Numbers, not names: which stiffness, and the device's limit.
    char line[240];
    if (c.method == physics::ForceMethod::M3 && c.alpha > 1.0)
      std::snprintf(line, sizeof line,
                    "a coupling stiffness of %g N/m (k_r %g N/m times alpha %g), more than the %g N/m the '%s' device "
                    "renders stably",
                    stiffest, c.stiffness, c.alpha, spec.maxStiffness, spec.name);
    else
      std::snprintf(line, sizeof line, "a coupling stiffness of %g N/m, more than the %g N/m the '%s' device renders stably",
                    stiffest, spec.maxStiffness, spec.name);
    return line;
  }
  return {};
}

ServoLoop::ServoLoop(const ServoLoopDef& def, HapticDevice& device)
    : def_(def),
      device_(device),
      system_(def.params, def.limits),
      stepper_(system_, integrator_, physics::forceStateOf(def.initialState), def.startTime),
      safety_(def.safety, device.spec()),
      coupling_(def.coupling) {
  if (!(def.period > 0.0) || !std::isfinite(def.period)) throw std::invalid_argument("ServoLoop: period must be positive");
  if (def.maxCatchUpTicks < 1) throw std::invalid_argument("ServoLoop: maxCatchUpTicks must be at least 1");
  if (def.recordEvery < 1) throw std::invalid_argument("ServoLoop: recordEvery must be at least 1");
  const std::string problem = couplingProblem(def.coupling, device.spec());
  if (!problem.empty())
    throw std::invalid_argument(problem.rfind("a coupling stiffness", 0) == 0 ? "the level asks for " + problem
                                                                               : "ServoLoop: " + problem);
  const std::string params = physics::validateParams(def.params, false);
  if (!params.empty()) throw std::invalid_argument("ServoLoop: " + params);
  const std::string guidance = guidanceProblem(def.guidance, device.spec());
  if (!guidance.empty()) throw std::invalid_argument("ServoLoop: guidance." + guidance);
}

ServoLoop::~ServoLoop() { stop(); }

void ServoLoop::start() {
  if (thread_.joinable()) return;
  stopRequested_.store(false, std::memory_order_relaxed);
  thread_ = std::thread([this] {
    if (def_.requestRealtime) {
      const RealtimeResult r = requestFifoScheduling(def_.realtimePriority);
      realtimeNote_.store(r.note, std::memory_order_relaxed);
      realtimeStatus_.store(static_cast<int>(r.status), std::memory_order_release);
    }
    SteadyServoClock steady(def_.spinMarginNs);
    runPaced(def_.clock != nullptr ? *def_.clock : steady, LONG_MAX);
    device_.sendForce(Vec3::Zero());
  });
}

void ServoLoop::stop() {
  if (!thread_.joinable()) return;
  stopRequested_.store(true, std::memory_order_relaxed);
  thread_.join();
}

RealtimeResult ServoLoop::realtime() const {
  const auto status = static_cast<RealtimeStatus>(realtimeStatus_.load(std::memory_order_acquire));
  return {status, realtimeNote_.load(std::memory_order_relaxed)};
}

LoopTimingSummary ServoLoop::timingSummary() const {
  LoopTimingSummary s;
  s.latenessP50 = lateness_.quantile(0.5);
  s.latenessP99 = lateness_.quantile(0.99);
  s.latenessP999 = lateness_.quantile(0.999);
  s.latenessMax = lateness_.max();
  s.periodP50 = period_.quantile(0.5);
  s.periodMax = period_.max();
  s.ticks = ticks();
  s.missedTicks = missedTicks();
  s.wakeups = wakeups();
  s.stalls = stalls();
  return s;
}

bool ServoLoop::post(const ServoCommand& command) {
  if (command.kind == ServoCommandKind::SetCoupling && !couplingProblem(command.coupling, device_.spec()).empty())
    return false;
  return commands_.push(command);
}

void ServoLoop::runHeadless(long n) {
  for (long i = 0; i < n; ++i) tick(0);
}

void ServoLoop::runPaced(ServoClock& clock, long maxWakeups) {
  const auto period = static_cast<std::int64_t>(std::llround(def_.period * 1e9));
  const auto catchUp = static_cast<std::int64_t>(def_.maxCatchUpTicks);
  const auto stallNs = static_cast<std::int64_t>(std::llround(std::min(def_.safety.maxTickLateness, 1e6) * 1e9));
  std::int64_t deadline = clock.now() + period;
  std::int64_t previousWake = -1;
  for (long w = 0; w < maxWakeups && !stopRequested_.load(std::memory_order_relaxed); ++w) {
    clock.waitUntil(deadline);
    const std::int64_t wake = clock.now();
    wakeups_.store(wakeups_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    if (previousWake >= 0) period_.record(wake - previousWake);
    previousWake = wake;
    if (wake - deadline > stallNs) stalls_.store(stalls_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    const std::int64_t due = 1 + std::max<std::int64_t>(wake - deadline, 0) / period;
    const std::int64_t run = std::min(due, catchUp);
    for (std::int64_t i = 0; i < run; ++i) {
      const std::int64_t late = clock.now() - (deadline + i * period);
      lateness_.record(late);
      tick(late);
    }
    if (due > run) {
      missed_.store(missed_.load(std::memory_order_relaxed) + static_cast<std::uint64_t>(due - run),
                    std::memory_order_relaxed);
      deadline = clock.now() + period;
    } else {
      deadline += run * period;
    }
  }
}

void ServoLoop::drainCommands() {
  ServoCommand c;
  // Bounded: at most the ring's capacity per tick.
  for (std::size_t i = 0; i < kCommandCapacity && commands_.pop(c); ++i) apply(c);
}

void ServoLoop::apply(const ServoCommand& c) {
  if (def_.commandRing != nullptr && !def_.commandRing->push(AppliedCommand{ticks_.load(std::memory_order_relaxed) + 1, c}))
    inputDropped_.store(inputDropped_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  switch (c.kind) {
    case ServoCommandKind::Engage: safety_.engage(); break;
    case ServoCommandKind::Disengage: safety_.disengage(); break;
    case ServoCommandKind::SetCoupling:
      coupling_ = c.coupling;
      if (system_.coupled()) system_.setCoupling(coupling_);
      break;
    case ServoCommandKind::ResetState:
      stepper_.reset(physics::forceStateOf(c.state), c.time);
      energyAtEngage_ = physics::mechanicalEnergy(system_.dynamics(), stepper_.state()).total();
      handWork_ = 0.0;
      if (safety_.fault() == SafetyFault::ModelHalted && !stepper_.halted()) safety_.clearFault();
      break;
    case ServoCommandKind::Pause: paused_ = true; break;
    case ServoCommandKind::Resume: paused_ = false; break;
    case ServoCommandKind::ClearFault: safety_.clearFault(); break;
  }
}

void ServoLoop::tick(std::int64_t latenessNs) {
  drainCommands();
  const double h = def_.period;

  // Device -> scene; the proxy is held for the whole step (zero-order hold).
  const DeviceReading reading = device_.read(stepper_.time());
  const char* deviceError = device_.error();
  if (def_.inputRing != nullptr) logInput(reading, latenessNs);
  proxy_.position = def_.mapping.positionToScene(reading.position);
  proxy_.velocity = def_.mapping.velocityToScene(reading.velocity);

  const bool coupled = safety_.engagement().coupled();
  if (coupled && !system_.coupled()) {
    system_.setCoupling(coupling_);
    system_.holdProxy(proxy_);
    energyAtEngage_ = physics::mechanicalEnergy(system_.dynamics(), stepper_.state()).total();
    handWork_ = 0.0;
    lastHandForce_ = system_.couplingForces(stepper_.time(), stepper_.state()).handForce;
  } else if (!coupled && system_.coupled()) {
    system_.setFree();
  }
  if (coupled) system_.holdProxy(proxy_);

  // Physics.
  const bool stepping = !paused_ && !safety_.faulted() && !stepper_.halted();
  if (stepping) stepper_.advance(h);
  const ForceDrivenState& x = stepper_.state();
  const physics::CouplingForces forces = system_.couplingForces(stepper_.time(), x);

  // Observations for the watchdogs.
  const physics::RollingGeometry g = physics::geometryOf(system_.dynamics().constants(), x);
  const Vec3 omega(x[physics::force_slot::w_x], x[physics::force_slot::w_y], x[physics::force_slot::w_z]);
  const physics::PointKinematics point =
      physics::pointKinematics(g, def_.params.radius, x[physics::force_slot::u_a], x[physics::force_slot::v_a], omega);
  const double distance = (point.position - proxy_.position).norm();
  double injected = 0.0;
  if (coupled) {
    // Work the hand does on the coupling (trapezoid over the step). In a
    // passive loop the model's energy gain never exceeds it (the difference
    // is the spring's energy and the damper's loss); with M1 the normal part
    // of F_h does no work on the model, which only lowers the estimate.
    if (stepping) handWork_ += 0.5 * (lastHandForce_ + forces.handForce).dot(proxy_.velocity) * h;
    lastHandForce_ = forces.handForce;
    injected = physics::mechanicalEnergy(system_.dynamics(), x).total() - energyAtEngage_ - handWork_;
  }

  lastGuidance_ = guidanceNow();

  SafetyInputs in;
  in.dt = h;
  in.desiredForce = def_.mapping.forceToDevice(forces.deviceForce + lastGuidance_);
  in.deviceVelocity = reading.velocity;
  in.devicePosition = reading.position;
  in.deviceError = deviceError != nullptr;
  in.deviceFresh = reading.fresh;
  in.newDevicePath = reading.newPath;
  in.modelHalted = stepper_.halted();
  in.proxyDistance = distance;
  in.injectedEnergy = injected;
  in.angularSpeed = omega.norm();
  in.tickLateness = static_cast<double>(latenessNs) * 1e-9;
  in.forceOff = paused_;  // a pause removes the force at once, not through the rate limit
  const Vec3 force = safety_.update(in);
  device_.safetyState(static_cast<std::uint8_t>(safety_.fault()));
  device_.sendForce(force);
  lastRendered_ = force;
  lastClamped_ = safety_.lastClamped();

  ticks_.store(ticks_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  publish(forces, distance, injected, latenessNs);
}

Vec3 ServoLoop::guidanceNow() {
  if (!def_.guidance.active()) return Vec3::Zero();
  guides_.read(guide_);  // keeps the previous plan when nothing new came
  return guidanceForce(def_.guidance, guide_, stepper_.time(), proxy_.position, proxy_.velocity);
}

void ServoLoop::publish(const physics::CouplingForces& forces, double distance, double injected,
                        std::int64_t latenessNs) {
  ServoSnapshot s;
  s.tick = ticks_.load(std::memory_order_relaxed);
  s.time = stepper_.time();
  const ForceDrivenState& x = stepper_.state();
  for (int i = 0; i < 12; ++i) s.state[static_cast<std::size_t>(i)] = x[i];
  s.proxyPosition = toTriple(proxy_.position);
  s.proxyVelocity = toTriple(proxy_.velocity);
  s.handForce = toTriple(forces.handForce);
  s.modelForce = toTriple(forces.modelForce);
  s.renderedForce = toTriple(lastRendered_);
  s.guidanceForce = toTriple(lastGuidance_);
  s.proxyDistance = distance;
  s.injectedEnergy = injected;
  s.event = stepper_.event();
  s.engagement = safety_.engagement().state();
  s.rampScale = safety_.engagement().scale();
  s.fault = safety_.fault();
  s.paused = paused_ || safety_.faulted();
  s.forceClamped = lastClamped_;
  s.lateness = static_cast<double>(latenessNs) * 1e-9;
  maxLateness_ = std::max(maxLateness_, s.lateness);
  s.maxLateness = maxLateness_;
  s.missedTicks = missed_.load(std::memory_order_relaxed);
  s.stalls = stalls_.load(std::memory_order_relaxed);
  snapshots_.write(s);
  if (plannerReads_.load(std::memory_order_relaxed)) plannerSnapshots_.write(s);
  if (def_.recordRing != nullptr && s.tick % static_cast<std::uint64_t>(def_.recordEvery) == 0 &&
      !def_.recordRing->push(recordRowOf(s)))
    recordDropped_.store(recordDropped_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
}

void ServoLoop::logInput(const DeviceReading& reading, std::int64_t latenessNs) {
  TickInput in;
  in.tick = ticks_.load(std::memory_order_relaxed) + 1;  // the tick now running
  in.position = toTriple(reading.position);
  in.velocity = toTriple(reading.velocity);
  in.buttons = reading.buttons;
  in.fresh = reading.fresh;
  in.newPath = reading.newPath;
  in.latenessNs = latenessNs;
  if (!def_.inputRing->push(in))
    inputDropped_.store(inputDropped_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
}

}  // namespace hemiroll::haptics
