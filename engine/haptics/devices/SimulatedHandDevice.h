#pragma once
// A test double for a real device held by a hand: the hand is a point mass
// pulled towards where the person means to be (an intent trajectory) by a
// spring and a damper (the arm's muscles), and pushed by the force the device
// renders. It closes the haptic loop in headless tests and, later, in the UDP
// bridge's reference client.
//
//   m_h a = k_h (r_intent - r) + b_h (v_intent - v) + F_rendered
//
// integrated by HandSpring (semi-implicit Euler) from one read() to the next,
// the intent sampled at each sub-step's start; the force sent after a read
// acts until the next one (zero-order hold, as on a real device).

#include <functional>

#include "engine/haptics/HandSpring.h"
#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

// The hand: the same spring-mass hand as the mouse's hand feel (mass, grip
// and arm stiffness, damping, longest sub-step).
using HandModelDef = HandSpringDef;

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

  const Vec3& position() const { return hand_.position(); }
  const Vec3& velocity() const { return hand_.velocity(); }

 private:
  IntentFunction intent_;
  HandSpring hand_;
  DeviceSpec spec_;
  double time_;
  Vec3 force_ = Vec3::Zero();
};

}  // namespace hemiroll::haptics
