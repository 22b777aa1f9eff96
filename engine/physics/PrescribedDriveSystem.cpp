#include "engine/physics/PrescribedDriveSystem.h"

#include <cmath>

namespace hemiroll::physics {

using namespace body_slot;

PrescribedDriveSystem::PrescribedDriveSystem(const HemisphereParams& params, const MassPointTrajectory& trajectory,
                                             const DomainLimits& limits)
    : dynamics_(params), trajectory_(trajectory), limits_(limits) {}

void PrescribedDriveSystem::derivative(double t, const BodyState& x, BodyState& dxdt) const {
  const ModelConstants& c = dynamics_.constants();
  const MassPointTrajectory::Sample s = trajectory_.at(t);
  const RollingGeometry g = makeGeometry(c, makeOrientation(x[u_o], x[v_o], x[psi]), s.p, s.pDot);
  const Vec3 omega = x.segment<3>(w_x);
  // Eq. (47): p'' does not enter the hemisphere's dynamics.
  const BodyAcceleration a = dynamics_.bodyAcceleration(g, omega, 0.0);
  const ContactRates rates = contactRates(g.orientation, c.params.radius, omega);
  dxdt.segment<3>(w_x) = a.omegaDot;
  dxdt[u_a] = rates.u_a;
  dxdt[v_a] = rates.v_a;
  dxdt[u_o] = rates.u_o;
  dxdt[v_o] = rates.v_o;
  dxdt[psi] = rates.psi;
}

DomainMargins PrescribedDriveSystem::margins(double t, const BodyState& x) const {
  const double radius = dynamics_.constants().params.radius;
  const Vec2 p = trajectory_.at(t).p;
  return {std::cos(x[u_o]) * std::cos(x[v_o]) - std::cos(limits_.maxTilt),
          limits_.maxPointRadius * radius - p.norm()};
}

Vec2 PrescribedDriveSystem::drivingForce(double t, const BodyState& x) const {
  const ModelConstants& c = dynamics_.constants();
  const MassPointTrajectory::Sample s = trajectory_.at(t);
  const RollingGeometry g = makeGeometry(c, makeOrientation(x[u_o], x[v_o], x[psi]), s.p, s.pDot);
  const BodyAcceleration a = dynamics_.bodyAcceleration(g, x.segment<3>(w_x), 0.0);
  return dynamics_.prescribedForce(g, a, s.pDDot);
}

ForceDrivenState PrescribedDriveSystem::fullState(double t, const BodyState& x) const {
  const MassPointTrajectory::Sample s = trajectory_.at(t);
  ForceDrivenState full;
  full << s.p, s.pDot, x;
  return full;
}

}  // namespace hemiroll::physics
