#pragma once
// Where the model stops being true. The paper's equations know neither limit:
// the contact must stay on the spherical part (tilt below the rim, where
// 1/cos v_o of eqs. 13 and 15 blows up), and the mass point must stay on the
// face disc. The stepper stops exactly at the edge and reports which one.

#include <cmath>

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

// A test that needs neither trigonometry nor a square root, for the stepper's
// check after every step (the exact tilt margin needs cos u_o and cos v_o,
// which cost as much as a fifth of an evaluation). It answers true only where
// the exact margins are certainly both >= 0, so that a state it passes
// classifies as None exactly as the margins would; near an edge, or for
// non-finite input, it answers false and the caller takes the exact margins.
// Why it is safe: cos u cos v >= cos(|u| + |v|) for |u|, |v| <= pi (the two
// differ by sin|u| sin|v| >= 0), and the bounds keep 1e-9 of room in cos and
// 1e-6 in |p|^2, far more than the few ulp of rounding in either margin.
class InteriorCheck {
 public:
  // cosMaxTilt is the value the exact tilt margin subtracts; faceLimit is
  // maxPointRadius * R [m], the value the exact face margin subtracts from.
  InteriorCheck(double cosMaxTilt, double faceLimit);

  bool surelyInside(double u_o, double v_o, double x_p, double y_p) const {
    return std::fabs(u_o) + std::fabs(v_o) <= tiltSumBound_ && x_p * x_p + y_p * y_p <= faceBoundSquared_;
  }
  // The two bounds, for the lanes' copy of this test (BatchedRk4.h).
  double tiltSumBound() const { return tiltSumBound_; }
  double faceBoundSquared() const { return faceBoundSquared_; }

 private:
  double tiltSumBound_;      // [rad], negative when no angle sum is safe
  double faceBoundSquared_;  // [m^2], negative when no radius is safe
};

const char* domainEventName(DomainEvent e);

}  // namespace hemiroll::physics
