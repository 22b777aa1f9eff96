#pragma once
// A simulated hand between a pointer and the proxy (issue 26, the mouse's
// "hand" feel): a point mass pulled towards the pointer by a spring and a
// damper (a relaxed arm's impedance) and pushed by the coupling force, as a
// real force device pushes the hand that holds it. The pointer is where the
// person puts the hand; the proxy is where the hand is.
//
//   m a = k (pointer - x) + b (pointer velocity - v) + F
//
// Semi-implicit Euler in sub-steps of at most maxStep. Used on the servo
// thread (MouseDevice::read) and by the human model's bot: no allocation, no
// locks, plain arithmetic.

#include <string>

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

// The figures are the human model's limb (engine/human/HumanDef.h LimbDef,
// docs/HUMAN_MODEL.md: Mussa-Ivaldi et al. 1985, Tsuji et al. 1995), the
// hand of SimulatedHandDevice (HandModelDef): a relaxed hand holding a stylus.
struct HandSpringDef {
  double mass = 0.3;          // [kg]
  double stiffness = 300.0;   // [N/m]
  double damping = 15.0;      // [N s/m]; about 0.8 of critical with these
  double maxStep = 0.001;     // longest integration sub-step [s]
  // Longest time one step() integrates; more (a stall, a pause) is dropped,
  // so that a late tick never asks for a burst of sub-steps [s].
  double maxGap = 0.1;
};

// "" when usable, else a sentence naming the bad field.
std::string validateHandSpring(const HandSpringDef& def);

class HandSpring {
 public:
  explicit HandSpring(const HandSpringDef& def = {}) : def_(def) {}

  // The hand at rest at `at` (the pointer jumped there).
  void reset(const Vec3& at);
  // Advance by dt [s] towards the pointer, pushed by `force` [N] (held
  // over the step). A non-finite input leaves the hand where it is.
  void step(const Vec3& pointer, const Vec3& pointerVelocity, const Vec3& force, double dt);

  const Vec3& position() const { return position_; }
  const Vec3& velocity() const { return velocity_; }
  const HandSpringDef& def() const { return def_; }

 private:
  HandSpringDef def_;
  Vec3 position_ = Vec3::Zero();
  Vec3 velocity_ = Vec3::Zero();
};

}  // namespace hemiroll::haptics
