#include "engine/haptics/ForceSafety.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::haptics {

ForceSafety::ForceSafety(const SafetyDef& def, const DeviceSpec& spec)
    : def_(def), maxForce_(spec.hasForceOutput ? spec.maxForce : 0.0), ramp_(def.engagement) {}

void ForceSafety::clearFault() {
  fault_ = SafetyFault::None;
  staleTime_ = 0.0;
  aboveContinuous_ = 0.0;
}

bool ForceSafety::outsideWorkspace(const Vec3& p) const {
  if (!(def_.workspaceHalfWidth > 0.0)) return false;
  const double m = def_.workspaceMargin;
  // Negated so that a NaN position counts as outside.
  return !(std::abs(p.x()) <= def_.workspaceHalfWidth + m && std::abs(p.y()) <= def_.workspaceHalfDepth + m &&
           std::abs(p.z()) <= def_.workspaceHalfHeight + m);
}

double ForceSafety::recentPath(const SafetyInputs& in) {
  if (in.newDevicePath) {
    steps_.fill(0.0);
    hasPosition_ = false;
  }
  const double step = hasPosition_ ? (in.devicePosition - lastPosition_).norm() : 0.0;
  lastPosition_ = in.devicePosition;
  hasPosition_ = true;
  steps_[static_cast<std::size_t>(stepIndex_)] = step;
  stepIndex_ = (stepIndex_ + 1) % kJumpWindow;
  double path = 0.0;
  for (const double s : steps_) path += s;
  return path;
}

SafetyFault ForceSafety::watchdogs(const SafetyInputs& in) {
  // Tracked every tick, faulted or not, so that the window is current when
  // a fault is cleared.
  const double path = recentPath(in);
  if (in.deviceError) return SafetyFault::DeviceError;
  staleTime_ = in.deviceFresh ? 0.0 : staleTime_ + in.dt;
  // Stale data holds a stale force only where one is rendered (issue 27:
  // the autopilot's hand on a mouse, left behind by a 60 ms stall its loop
  // caught up, stopped the game for data that held nothing).
  if (maxForce_ > 0.0 && staleTime_ > def_.staleLimit) return SafetyFault::StaleDevice;
  // Negated comparisons so that NaN observations trip the guard.
  if (!(in.deviceVelocity.norm() <= def_.maxDeviceSpeed)) return SafetyFault::VelocityGuard;
  // Only where a force is rendered: a mouse has none to send into a
  // teleporting hand, and its strokes may arrive faster in a flick.
  if (maxForce_ > 0.0 && !(path <= def_.maxDeviceSpeed * kJumpWindow * in.dt)) return SafetyFault::PositionJump;
  if (in.modelHalted) return SafetyFault::ModelHalted;
  // A late tick is a hazard only where a force is rendered: the device held
  // the last force that long. A mouse has none (issue 27: a single 23 ms
  // tick stopped mouse play); its loop catches up or slows its clock.
  if (maxForce_ > 0.0 && !(in.tickLateness <= def_.maxTickLateness)) return SafetyFault::LoopOverrun;
  if (!(in.injectedEnergy <= def_.maxInjectedEnergy)) return SafetyFault::EnergyInjection;
  if (!(in.angularSpeed <= def_.maxAngularSpeed)) return SafetyFault::RunawayRotation;
  if (!in.desiredForce.allFinite()) return SafetyFault::NonFiniteForce;
  if (maxForce_ > 0.0 && outsideWorkspace(in.devicePosition)) return SafetyFault::OutsideWorkspace;
  // The force sent last tick (what the motors hold now) against the rating.
  if (def_.continuousForce > 0.0) {
    aboveContinuous_ = last_.norm() > def_.continuousForce ? aboveContinuous_ + in.dt : 0.0;
    if (aboveContinuous_ > def_.aboveContinuousLimit) return SafetyFault::ForceSaturated;
  }
  return SafetyFault::None;
}

Vec3 ForceSafety::update(const SafetyInputs& in) {
  clamped_ = false;
  const SafetyFault now = watchdogs(in);
  if (fault_ == SafetyFault::None) fault_ = now;
  if (fault_ != SafetyFault::None) {
    ramp_.dropNow();
    last_ = Vec3::Zero();
    return last_;
  }
  ramp_.update(in.dt, in.proxyDistance);
  if (in.forceOff) {
    last_ = Vec3::Zero();
    return last_;
  }
  const Vec3 target = ramp_.scale() * in.desiredForce;
  const Vec3 limited = limitForceStep(last_, target, def_.maxForceRate * in.dt);
  const ClampResult c = clampForce(limited, maxForce_);
  if (c.nonFinite) {  // unreachable after the watchdog, kept as the clamp's own guarantee
    fault_ = SafetyFault::NonFiniteForce;
    ramp_.dropNow();
    last_ = Vec3::Zero();
    return last_;
  }
  clamped_ = c.clamped;
  last_ = c.force;
  return last_;
}

const char* safetyFaultName(SafetyFault f) {
  switch (f) {
    case SafetyFault::None: return "none";
    case SafetyFault::DeviceError: return "device error";
    case SafetyFault::StaleDevice: return "stale device data";
    case SafetyFault::NonFiniteForce: return "non-finite force";
    case SafetyFault::VelocityGuard: return "device velocity above the guard";
    case SafetyFault::PositionJump: return "device position jumped (faster than the velocity guard)";
    case SafetyFault::EnergyInjection: return "energy injection beyond the bound";
    case SafetyFault::RunawayRotation: return "runaway angular velocity";
    case SafetyFault::ModelHalted: return "model halted at a domain edge";
    case SafetyFault::LoopOverrun: return "servo loop stalled";
    case SafetyFault::OutsideWorkspace: return "device outside its workspace";
    case SafetyFault::ForceSaturated: return "force held above the device's continuous rating too long";
  }
  return "?";
}

}  // namespace hemiroll::haptics
