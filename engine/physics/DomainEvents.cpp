#include "engine/physics/DomainEvents.h"

#include <cmath>

namespace hemiroll::physics {

DomainEvent classifyDomain(const DomainMargins& m, bool finite) {
  // A NaN margin compares false everywhere, so test finiteness first.
  if (!finite || !std::isfinite(m.tilt) || !std::isfinite(m.face)) return DomainEvent::NonFinite;
  if (m.tilt < 0.0) return DomainEvent::TippedOver;
  if (m.face < 0.0) return DomainEvent::LeftFace;
  return DomainEvent::None;
}

InteriorCheck::InteriorCheck(double cosMaxTilt, double faceLimit) {
  // cos(|u| + |v|) >= cosMaxTilt + 1e-9 wherever |u| + |v| <= tiltSumBound_,
  // with a relative 1e-9 more off the angle for the rounding of acos and of
  // the sum |u| + |v|.
  const double cosNeeded = cosMaxTilt + 1e-9;
  tiltSumBound_ = cosNeeded < 1.0 ? std::acos(cosNeeded) * (1.0 - 1e-9) : -1.0;
  // |p|^2 <= (1 - 1e-6) faceLimit^2 keeps sqrt(|p|^2) well below faceLimit
  // after every rounding.
  faceBoundSquared_ = faceLimit > 0.0 ? faceLimit * faceLimit * (1.0 - 1e-6) : -1.0;
}

const char* domainEventName(DomainEvent e) {
  switch (e) {
    case DomainEvent::None: return "none";
    case DomainEvent::TippedOver: return "tipped_over";
    case DomainEvent::LeftFace: return "left_face";
    case DomainEvent::NonFinite: return "non_finite";
  }
  return "?";
}

}  // namespace hemiroll::physics
