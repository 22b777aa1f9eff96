#pragma once
// Everything between the coupling's force and the device, applied on every
// tick in this order:
//   1. watchdogs: device error, stale device data for longer than staleLimit,
//      a servo tick that started more than maxTickLateness after its deadline
//      (these two on a device that renders force: stale data or a late tick
//      held a stale force that long; a device without force output, the
//      mouse, has none to hold, and the loop rides the late tick out instead,
//      ServoLoop.h),
//      device speed above maxDeviceSpeed (velocity guard), energy injected
//      into the model beyond maxInjectedEnergy, angular speed beyond
//      maxAngularSpeed, a non-finite force; with a device profile's limits
//      (game/trial/DeviceProfiles), the device's position outside its
//      workspace box, and the force held above the device's continuous rating
//      for longer than aboveContinuousLimit. Any of them latches a fault: the
//      force is zero from this very tick (no fade, no rate limit), the
//      engagement is dropped, and the loop pauses until clearFault().
//   2. engagement and ramp (EngagementRamp): scale in [0, 1].
//   3. force-rate limit: |F_k - F_{k-1}| <= maxForceRate * dt.
//   4. clamp to the device's maxForce (ForceClamp.h) - last, so nothing after
//      it can lengthen the force.

#include <array>

#include "engine/haptics/EngagementRamp.h"
#include "engine/haptics/ForceClamp.h"

namespace hemiroll::haptics {

enum class SafetyFault {
  None,
  DeviceError,       // the device reported an error
  StaleDevice,       // no fresh sample for longer than staleLimit
  NonFiniteForce,    // the coupling produced NaN or Inf
  VelocityGuard,     // the device moved faster than maxDeviceSpeed
  EnergyInjection,   // the model gained more energy than the hand supplied, beyond the bound
  RunawayRotation,   // the hemisphere spins faster than maxAngularSpeed
  ModelHalted,       // the physics stopped at a domain edge (tip-over, off-face, non-finite)
  LoopOverrun,       // the servo loop stalled: a tick started too late
  PositionJump,      // the device's positions moved faster than maxDeviceSpeed, whatever velocity it reported
  OutsideWorkspace,  // the device reported a position outside its workspace box (wrong units or origin?)
  ForceSaturated,    // the force stayed above the device's continuous rating for longer than allowed
};

struct SafetyDef {
  EngagementDef engagement;
  double maxForceRate = 200.0;      // [N/s]; 0.2 N per 1 ms tick, a full 3 N swing in 15 ms
  double maxDeviceSpeed = 2.0;      // [m/s], device frame; beyond any deliberate hand motion on a desk device
  double staleLimit = 0.010;        // [s] without a fresh device sample
  double maxInjectedEnergy = 0.5;   // [J] model energy gained beyond the hand's work (see ServoLoop)
  double maxAngularSpeed = 200.0;   // [rad/s] |w| of the hemisphere
  // [s] a tick starting this late means the device held a stale force that
  // long; well above the scheduler hiccups of a loaded desktop (a few ms).
  double maxTickLateness = 0.020;
  // A device profile's limits (zero: not checked, as for a device without a
  // profile). The box is centred on the device's origin [m]; a position
  // beyond it by more than workspaceMargin means the client's units or
  // origin are wrong, or the handle slipped its mechanical stops.
  double workspaceHalfWidth = 0.0, workspaceHalfDepth = 0.0, workspaceHalfHeight = 0.0;  // [m]
  double workspaceMargin = 0.0;        // [m]
  // [N] the force a device may hold indefinitely (its motors' thermal
  // rating); above it for longer than aboveContinuousLimit [s] is a stop.
  double continuousForce = 0.0;
  double aboveContinuousLimit = 0.0;
};

// Per-tick observations the watchdogs judge.
struct SafetyInputs {
  double dt = 0.001;                   // [s]
  Vec3 desiredForce = Vec3::Zero();    // device frame, before safety [N]
  Vec3 deviceVelocity = Vec3::Zero();  // device frame [m/s]
  Vec3 devicePosition = Vec3::Zero();  // device frame [m]
  bool deviceError = false;
  bool deviceFresh = true;
  bool newDevicePath = false;          // DeviceReading::newPath: the jump window restarts
  bool modelHalted = false;
  double proxyDistance = 0.0;          // proxy to mass point, scene [m]
  double injectedEnergy = 0.0;         // [J]
  double angularSpeed = 0.0;           // [rad/s]
  double tickLateness = 0.0;           // this tick's start after its deadline [s]
  // The loop is paused: the watchdogs still run, the force is zero at once,
  // and the rate limit restarts from zero when the pause ends.
  bool forceOff = false;
};

class ForceSafety {
 public:
  ForceSafety(const SafetyDef& def, const DeviceSpec& spec);

  // The force to send to the device this tick (device frame) [N].
  Vec3 update(const SafetyInputs& in);

  void engage() { ramp_.engage(); }
  void disengage() { ramp_.disengage(); }
  // Unlatches the fault (the operator saw it); a cause still present trips
  // it again on the next tick.
  void clearFault();

  SafetyFault fault() const { return fault_; }
  bool faulted() const { return fault_ != SafetyFault::None; }
  const EngagementRamp& engagement() const { return ramp_; }
  const Vec3& lastForce() const { return last_; }
  bool lastClamped() const { return clamped_; }
  double staleTime() const { return staleTime_; }
  // How long the force sent has stayed above the continuous rating [s].
  double aboveContinuousTime() const { return aboveContinuous_; }

 private:
  SafetyFault watchdogs(const SafetyInputs& in);
  // The device's path length over the last kJumpWindow ticks, this tick's step included.
  double recentPath(const SafetyInputs& in);
  bool outsideWorkspace(const Vec3& p) const;

  // The position guard looks at the path over 10 ticks, not one: a mouse's
  // strokes arrive once per frame (16 ms of motion in one tick), while a
  // device teleporting every tick covers metres per second however it is
  // sampled and whatever velocity it reports.
  static constexpr int kJumpWindow = 10;

  SafetyDef def_;
  double maxForce_;
  EngagementRamp ramp_;
  SafetyFault fault_ = SafetyFault::None;
  Vec3 last_ = Vec3::Zero();
  bool clamped_ = false;
  double staleTime_ = 0.0;
  double aboveContinuous_ = 0.0;  // [s] of consecutive ticks with |last_| above continuousForce
  std::array<double, kJumpWindow> steps_{};  // [m] per tick, a ring
  int stepIndex_ = 0;
  bool hasPosition_ = false;
  Vec3 lastPosition_ = Vec3::Zero();
};

const char* safetyFaultName(SafetyFault f);

}  // namespace hemiroll::haptics
