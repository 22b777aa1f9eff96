#pragma once
// Interaction starts only when the user asks for it and brings the proxy
// near the mass point (the paper's engagement), and the rendered force fades
// in over rampTime rather than arriving as a step. Disengaging fades it out.
//
//   Disengaged --engage()--> Armed --proxy within engageDistance--> Engaged
//   Engaged/Armed --disengage()--> RampingOut --scale reaches 0--> Disengaged
//   any --dropNow()--> Disengaged, scale 0 (faults: no fade, force off at once)
//
// The scale rises and falls linearly at 1 / rampTime per second.

namespace hemiroll::haptics {

enum class Engagement { Disengaged, Armed, Engaged, RampingOut };

struct EngagementDef {
  double engageDistance = 0.01;  // proxy to mass point distance that engages [m], scene frame
  double rampTime = 1.0;         // fade-in and fade-out time [s]
};

class EngagementRamp {
 public:
  explicit EngagementRamp(const EngagementDef& def = {}) : def_(def) {}

  void engage();
  void disengage();
  void dropNow();
  // Once per tick of dt [s], with the current proxy to mass point distance [m].
  void update(double dt, double proxyDistance);

  Engagement state() const { return state_; }
  double scale() const { return scale_; }  // [0, 1], multiplies the rendered force
  // The model is coupled to the proxy while the user holds it (also during
  // the fade-out, so the force felt stays the force of the model).
  bool coupled() const { return state_ == Engagement::Engaged || state_ == Engagement::RampingOut; }
  const EngagementDef& def() const { return def_; }

 private:
  EngagementDef def_;
  Engagement state_ = Engagement::Disengaged;
  double scale_ = 0.0;
};

const char* engagementName(Engagement e);

}  // namespace hemiroll::haptics
