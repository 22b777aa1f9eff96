#include "engine/haptics/ForceSafety.h"

#include <algorithm>

namespace hemiroll::haptics {

ForceSafety::ForceSafety(const SafetyDef& def, const DeviceSpec& spec)
    : def_(def), maxForce_(spec.hasForceOutput ? spec.maxForce : 0.0), ramp_(def.engagement) {}

void ForceSafety::clearFault() {
  fault_ = SafetyFault::None;
  staleTime_ = 0.0;
}

SafetyFault ForceSafety::watchdogs(const SafetyInputs& in) {
  if (in.deviceError) return SafetyFault::DeviceError;
  staleTime_ = in.deviceFresh ? 0.0 : staleTime_ + in.dt;
  if (staleTime_ > def_.staleLimit) return SafetyFault::StaleDevice;
  // Negated comparisons so that NaN observations trip the guard.
  if (!(in.deviceVelocity.norm() <= def_.maxDeviceSpeed)) return SafetyFault::VelocityGuard;
  if (in.modelHalted) return SafetyFault::ModelHalted;
  if (!(in.tickLateness <= def_.maxTickLateness)) return SafetyFault::LoopOverrun;
  if (!(in.injectedEnergy <= def_.maxInjectedEnergy)) return SafetyFault::EnergyInjection;
  if (!(in.angularSpeed <= def_.maxAngularSpeed)) return SafetyFault::RunawayRotation;
  if (!in.desiredForce.allFinite()) return SafetyFault::NonFiniteForce;
  return SafetyFault::None;
}

Vec3 ForceSafety::update(const SafetyInputs& in) {
  clamped_ = false;
  if (fault_ == SafetyFault::None) fault_ = watchdogs(in);
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
    case SafetyFault::EnergyInjection: return "energy injection beyond the bound";
    case SafetyFault::RunawayRotation: return "runaway angular velocity";
    case SafetyFault::ModelHalted: return "model halted at a domain edge";
    case SafetyFault::LoopOverrun: return "servo loop stalled";
  }
  return "?";
}

}  // namespace hemiroll::haptics
