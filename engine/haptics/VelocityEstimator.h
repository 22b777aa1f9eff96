#pragma once
// Velocity of an input that only reports positions (mouse, joystick axes):
// a finite difference between samples, clamped, then a first-order low-pass.
//
//   raw = (p_k - p_{k-1}) / (t_k - t_{k-1})   when a new sample arrives, with
//         |raw| <= maxSpeed (a jump of the pointer is not a velocity);
//   raw = 0                                   after holdTime without a sample
//                                             (the input stopped moving);
//   v  += (1 - exp(-h / timeConstant)) (raw - v)   every update, h = time since
//                                             the previous update.
// Differences are taken between samples, not between updates, so a 125 Hz
// mouse read at 1 kHz gives its real speed rather than one spike and seven
// zeros. reset() marks a discontinuity (the pointer re-entered the window):
// the velocity restarts from zero at the new position.

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

struct VelocityFilterDef {
  double timeConstant = 0.02;  // [s]; smooths the 8 ms steps of a 125 Hz mouse, lags a hand by little
  double maxSpeed = 1.0;       // [m/s]; half the safety layer's velocity guard (2 m/s)
  double holdTime = 0.05;      // [s]; longer than a frame at 30 Hz, the slowest UI feeding us
};

class VelocityEstimator {
 public:
  explicit VelocityEstimator(const VelocityFilterDef& def = {});

  // t [s] on any monotonic clock; newSample says whether position is new.
  const Vec3& update(double t, const Vec3& position, bool newSample);
  void reset(double t, const Vec3& position);
  const Vec3& velocity() const { return velocity_; }

 private:
  VelocityFilterDef def_;
  bool started_ = false;
  double lastUpdate_ = 0.0, lastSampleTime_ = 0.0;
  Vec3 lastSample_ = Vec3::Zero(), raw_ = Vec3::Zero(), velocity_ = Vec3::Zero();
};

}  // namespace hemiroll::haptics
