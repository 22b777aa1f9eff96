#include "engine/physics/Energy.h"

#include "engine/physics/ForceCoupling.h"
#include "engine/physics/ForceDrivenSystem.h"

namespace hemiroll::physics {

using namespace force_slot;

EnergyTerms mechanicalEnergy(const RollingDynamics& dynamics, const StateVector<12>& x) {
  const ModelConstants& c = dynamics.constants();
  const HemisphereParams& p = c.params;
  const RollingGeometry g = geometryOf(c, x);
  const Vec3 omega = x.segment<3>(w_x);
  // The contact point is the instantaneous centre of rotation: T_s = w J_c w / 2,
  // with w and J_c both in the heading frame.
  const Vec3 omegaH = g.frame.toHeading(Real3::from(omega)).eigen();
  const double shell = 0.5 * omegaH.dot(dynamics.contactInertia(g.frame.k.eigen()) * omegaH);
  const Vec3 vp = pointKinematics(g, p.radius, x[u_a], x[v_a], omega).velocity;
  const double zShell = p.radius - c.comDepth * g.frame.k.z;
  const double zPoint = p.radius + g.rhoP.z;
  return {shell + 0.5 * p.pointMass * vp.squaredNorm(), p.gravity * (p.shellMass * zShell + p.pointMass * zPoint)};
}

double externalPower(const RollingDynamics& dynamics, const StateVector<12>& x, const Vec3& force) {
  const ModelConstants& c = dynamics.constants();
  const RollingGeometry g = geometryOf(c, x);
  return force.dot(pointKinematics(g, c.params.radius, x[u_a], x[v_a], x.segment<3>(w_x)).velocity);
}

}  // namespace hemiroll::physics
