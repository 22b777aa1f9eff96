#include "engine/haptics/EngagementRamp.h"

#include <algorithm>

namespace hemiroll::haptics {

void EngagementRamp::engage() {
  // Engaging during a fade-out picks the force up where it is.
  if (state_ == Engagement::Disengaged) state_ = Engagement::Armed;
  if (state_ == Engagement::RampingOut) state_ = Engagement::Engaged;
}

void EngagementRamp::disengage() {
  if (state_ == Engagement::Armed) state_ = Engagement::Disengaged;
  if (state_ == Engagement::Engaged) state_ = Engagement::RampingOut;
}

void EngagementRamp::dropNow() {
  state_ = Engagement::Disengaged;
  scale_ = 0.0;
}

void EngagementRamp::update(double dt, double proxyDistance) {
  const double step = def_.rampTime > 0.0 ? dt / def_.rampTime : 1.0;
  switch (state_) {
    case Engagement::Disengaged: scale_ = 0.0; break;
    case Engagement::Armed:
      if (proxyDistance <= def_.engageDistance) state_ = Engagement::Engaged;
      break;
    case Engagement::Engaged: scale_ = std::min(1.0, scale_ + step); break;
    case Engagement::RampingOut:
      scale_ = std::max(0.0, scale_ - step);
      if (scale_ == 0.0) state_ = Engagement::Disengaged;
      break;
  }
}

const char* engagementName(Engagement e) {
  switch (e) {
    case Engagement::Disengaged: return "disengaged";
    case Engagement::Armed: return "armed";
    case Engagement::Engaged: return "engaged";
    case Engagement::RampingOut: return "ramping out";
  }
  return "?";
}

}  // namespace hemiroll::haptics
