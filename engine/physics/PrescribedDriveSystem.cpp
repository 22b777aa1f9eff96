#include "engine/physics/PrescribedDriveSystem.h"

#include <cmath>

namespace hemiroll::physics {

using namespace body_slot;

namespace {
RollingGeometry geometryAt(const ModelConstants& c, const BodyState& x, const MassPointTrajectory::Sample& s) {
  return makeGeometry(c, makeHeadingFrame(x[u_o], x[v_o], x[psi]), Real2::from(s.p), Real2::from(s.pDot));
}
}  // namespace

PrescribedDriveSystem::PrescribedDriveSystem(const HemisphereParams& params, const MassPointTrajectory& trajectory,
                                             const DomainLimits& limits)
    : dynamics_(params),
      trajectory_(trajectory),
      limits_(limits),
      cosMaxTilt_(std::cos(limits.maxTilt)),
      interior_(cosMaxTilt_, limits.maxPointRadius * params.radius) {}

// flatten: the whole evaluation compiled as one function (geometry, sin/cos,
// the 3x3 solve). Left to GCC's size limits, parts of it stay
// out of line and pass their results through memory (docs/PERFORMANCE.md).
[[gnu::flatten]] void PrescribedDriveSystem::derivative(double t, const BodyState& x, BodyState& dxdt) const {
  const MassPointTrajectory::Sample s = trajectory_.at(t);
  prescribedRatesOf(dynamics_.massConstants(), Real2::from(s.p), Real2::from(s.pDot), x.data(), dxdt.data());
}

DomainMargins PrescribedDriveSystem::margins(double t, const BodyState& x) const {
  const double radius = dynamics_.constants().params.radius;
  const Vec2 p = trajectory_.at(t).p;
  SinCos u, v;
  sinCos2(x[u_o], x[v_o], u, v);
  return {u.cos * v.cos - cosMaxTilt_,
          limits_.maxPointRadius * radius - std::sqrt(p.squaredNorm())};
}

DomainEvent PrescribedDriveSystem::domainEvent(double t, const BodyState& x) const {
  return domainEventWith(t, x, trajectory_.at(t).p);
}

DomainEvent PrescribedDriveSystem::domainEventWith(double t, const BodyState& x, const Vec2& p) const {
  if (interior_.surelyInside(x[u_o], x[v_o], p.x(), p.y()) && x.allFinite()) return DomainEvent::None;
  return OdeSystem::domainEvent(t, x);
}

Vec2 PrescribedDriveSystem::drivingForce(double t, const BodyState& x) const {
  const ModelConstants& c = dynamics_.constants();
  const MassPointTrajectory::Sample s = trajectory_.at(t);
  const RollingGeometry g = geometryAt(c, x, s);
  const BodyAcceleration a = dynamics_.bodyAcceleration(g, g.frame.toHeading({x[w_x], x[w_y], x[w_z]}), 0.0);
  return dynamics_.prescribedForce(g, a, Real2::from(s.pDDot)).eigen();
}

ForceDrivenState PrescribedDriveSystem::fullState(double t, const BodyState& x) const {
  const MassPointTrajectory::Sample s = trajectory_.at(t);
  ForceDrivenState full;
  full << s.p, s.pDot, x;
  return full;
}

}  // namespace hemiroll::physics
