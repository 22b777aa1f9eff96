#pragma once
// A person playing through a device, tick by tick:
//
//   screen now -> ViewDelay (visualDelay) -> at most every `interval`:
//       a decision (the hint when the game shows one, else the Technique)
//       -> motor noise -> MotorPlan (a blended submovement)
//   -> intent -> Limb (pushed by the rendered force on a haptic device)
//   -> the proxy pose the device reads.
//
// Deterministic per seed. No allocation after construction.

#include <cstdint>

#include "engine/human/HumanDef.h"
#include "engine/human/Limb.h"
#include "engine/human/MotorPlan.h"
#include "engine/human/ScreenView.h"
#include "engine/human/Technique.h"
#include "engine/human/ViewDelay.h"
#include "engine/physics/NormalDraws.h"

namespace hemiroll::human {

struct HandPose {
  physics::Vec3 position = physics::Vec3::Zero();  // scene [m]
  physics::Vec3 velocity = physics::Vec3::Zero();  // scene [m/s]
};

// For tests and the issue note: what the person did.
struct HumanStats {
  long long corrections = 0;
  double firstCorrection = -1.0;       // when the first correction was made [s]; -1 before
  double shortestInterval = 1e30;      // between two corrections [s]
  double largestLag = 0.0;             // age of the view a correction used [s]
  double smallestLag = 1e30;           // [s]
  long long hintCorrections = 0;       // corrections that followed the hint
};

class HumanModel {
 public:
  // `radius`: the hemisphere's, as the person sees it [m]; `tick` [s].
  HumanModel(const HumanDef& def, const TechniqueDef& technique, double radius, double tick, std::uint64_t seed);

  // Takes hold where the mass point is, hand and intent at rest there.
  void takeHold(const physics::Vec3& at);
  // One tick: what the screen shows now, and the force the device renders
  // on the hand (scene frame [N]; a mouse's is ignored).
  HandPose act(const ScreenView& now, const physics::Vec3& deviceForce);

  const HumanDef& def() const { return def_; }
  const HumanStats& stats() const { return stats_; }
  const Technique& technique() const { return technique_; }

 private:
  Movement decide(const ScreenView& seen);
  Movement withNoise(Movement m);
  // Whether `wanted` differs enough from what the hand is doing to act on.
  bool worthCorrecting(const Movement& wanted) const;

  HumanDef def_;
  double tick_;
  ViewDelay delay_;
  Technique technique_;
  MotorPlan plan_;
  Limb limb_;
  physics::NormalDraws normal_;
  double lastDecision_ = -1e30;
  double lastCorrection_ = -1e30;
  HumanStats stats_;
};

}  // namespace hemiroll::human
