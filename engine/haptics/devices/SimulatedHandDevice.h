#pragma once
// A test double for a real device held by a hand: the hand is a point mass
// pulled towards where the person means to be (an intent trajectory) by a
// spring and a damper (the arm's muscles), and pushed by the force the device
// renders. It closes the haptic loop in headless tests and, later, in the UDP
// bridge's reference client.
//
//   m_h a = k_h (r_intent - r) + b_h (v_intent - v) + F_rendered
//
// integrated with semi-implicit Euler from one read() to the next (the time
// between two reads is the servo period); the force sent after a read acts
// until the next one (zero-order hold, as on a real device).

#include <functional>

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

struct HandModelDef {
  double mass = 0.3;          // m_h, effective hand and device mass [kg]
  double stiffness = 300.0;   // k_h, grip and arm stiffness [N/m]
  double damping = 15.0;      // b_h [N s/m]; about 0.8 of critical for these values
  double maxStep = 0.001;     // longest integration sub-step [s] (stability of the explicit part)
};

class SimulatedHandDevice final : public HapticDevice {
 public:
  struct Intent {
    Vec3 position = Vec3::Zero();  // device coordinates [m]
    Vec3 velocity = Vec3::Zero();  // [m/s]
  };
  using IntentFunction = std::function<Intent(double t)>;

  // The hand starts at rest at intent(t0).
  SimulatedHandDevice(IntentFunction intent, const HandModelDef& hand = {}, const DeviceSpec& spec = {},
                      double t0 = 0.0);

  const DeviceSpec& spec() const override { return spec_; }
  bool open() override { return true; }
  void close() override {}
  DeviceReading read(double t) override;
  void sendForce(const Vec3& force) override { force_ = force; }
  const char* error() const override { return nullptr; }

  const Vec3& position() const { return position_; }
  const Vec3& velocity() const { return velocity_; }

 private:
  IntentFunction intent_;
  HandModelDef hand_;
  DeviceSpec spec_;
  double time_;
  Vec3 position_, velocity_ = Vec3::Zero();
  Vec3 force_ = Vec3::Zero();
};

}  // namespace hemiroll::haptics
