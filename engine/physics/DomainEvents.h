#pragma once
// Where the model stops being true. The paper's equations know neither limit:
// the contact must stay on the spherical part (tilt below the rim, where
// 1/cos v_o of eqs. 13 and 15 blows up), and the mass point must stay on the
// face disc. The stepper stops exactly at the edge and reports which one.

namespace hemiroll::physics {

struct DomainLimits {
  double maxTilt = 1.5707963267948966;  // [rad] angle of the face normal from vertical; pi/2 = rim on the plane
  double maxPointRadius = 1.0;          // [R] largest |p| as a fraction of the radius; 1 = face edge
};

enum class DomainEvent {
  None,
  TippedOver,  // the contact reached the rim: tilt >= maxTilt
  LeftFace,    // the mass point reached the edge of the face disc
  NonFinite,   // a step produced Inf/NaN without crossing either edge (e.g. an unstable coupling)
};

// Signed distances to the two edges, both >= 0 inside the domain.
struct DomainMargins {
  double tilt;  // cos(tilt) - cos(maxTilt) [-]
  double face;  // maxPointRadius * R - |p| [m]
};

// Which edge a state has crossed (None when inside and finite).
DomainEvent classifyDomain(const DomainMargins& m, bool finite);

const char* domainEventName(DomainEvent e);

}  // namespace hemiroll::physics
