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
