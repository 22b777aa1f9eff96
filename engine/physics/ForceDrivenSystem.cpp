#include "engine/physics/ForceDrivenSystem.h"

#include <cmath>

namespace hemiroll::physics {

using namespace force_slot;

namespace {
Real2 pointOf(const ForceDrivenState& x) { return {x[x_p], x[y_p]}; }
Real2 pointRateOf(const ForceDrivenState& x) { return {x[xd_p], x[yd_p]}; }
Real3 omegaOf(const ForceDrivenState& x) { return {x[w_x], x[w_y], x[w_z]}; }
}  // namespace

RollingGeometry geometryOf(const ModelConstants& c, const ForceDrivenState& x) {
  return makeGeometry(c, makeHeadingFrame(x[u_o], x[v_o], x[psi]), pointOf(x), pointRateOf(x));
}

ForceDrivenSystem::ForceDrivenSystem(const HemisphereParams& params, const DomainLimits& limits)
    : dynamics_(params),
      limits_(limits),
      cosMaxTilt_(std::cos(limits.maxTilt)),
      interior_(cosMaxTilt_, limits.maxPointRadius * params.radius) {}

Real3 ForceDrivenSystem::handForceAt(const RollingGeometry& g, double t, const ForceDrivenState& x,
                                     const Real3& omegaH) const {
  const HeadingFrame& f = g.frame;
  const Real3 centre{x[u_a], x[v_a], dynamics_.constants().params.radius};
  return input_.handForce(t, f.k, centre, g.rhoP, cross(omegaH, g.lever) + g.rhoPDot,
                          [&f](const Real3& v) { return f.toHeading(v); });
}

Real3 ForceDrivenSystem::inputForce(const RollingGeometry& g, double t, const ForceDrivenState& x,
                                    const Real3& omegaH) const {
  switch (input_.mode()) {
    case ForceInput::Mode::Free: return {0.0, 0.0, 0.0};
    case ForceInput::Mode::FaceForce: return g.frame.inPlane(Real2::from(input_.faceForce()));
    case ForceInput::Mode::Coupling: return modelForce(input_.coupling(), g.frame.k, handForceAt(g, t, x, omegaH));
  }
  return {0.0, 0.0, 0.0};
}

// flatten: the whole evaluation compiled as one function (geometry, sin/cos,
// input force, the 3x3 solve). Left to GCC's size limits, parts of it stay
// out of line and pass their results through memory (docs/PERFORMANCE.md).
[[gnu::flatten]] void ForceDrivenSystem::derivative(double t, const ForceDrivenState& x, ForceDrivenState& dxdt) const {
  forceDrivenRatesOf(dynamics_.massConstants(), x.data(), dxdt.data(),
                     [&](const RollingGeometry& g, const Real3& omegaH) { return inputForce(g, t, x, omegaH); });
}

DomainMargins ForceDrivenSystem::margins(double, const ForceDrivenState& x) const {
  const double radius = dynamics_.constants().params.radius;
  SinCos u, v;
  sinCos2(x[u_o], x[v_o], u, v);
  return {u.cos * v.cos - cosMaxTilt_,
          limits_.maxPointRadius * radius - std::sqrt(x[x_p] * x[x_p] + x[y_p] * x[y_p])};
}

DomainEvent ForceDrivenSystem::domainEvent(double t, const ForceDrivenState& x) const {
  if (interior_.surelyInside(x[u_o], x[v_o], x[x_p], x[y_p]) && x.allFinite()) return DomainEvent::None;
  return OdeSystem::domainEvent(t, x);
}

Vec3 ForceDrivenSystem::externalForce(double t, const ForceDrivenState& x) const {
  const RollingGeometry g = geometryOf(dynamics_.constants(), x);
  return g.frame.toBase(inputForce(g, t, x, g.frame.toHeading(omegaOf(x)))).eigen();
}

CouplingForces ForceDrivenSystem::couplingForces(double t, const ForceDrivenState& x) const {
  const RollingGeometry g = geometryOf(dynamics_.constants(), x);
  const HeadingFrame& f = g.frame;
  const Real3 omegaH = f.toHeading(omegaOf(x));
  if (!coupled()) return {Vec3::Zero(), f.toBase(inputForce(g, t, x, omegaH)).eigen(), Vec3::Zero()};
  const Real3 hand = handForceAt(g, t, x, omegaH);
  const Vec3 handBase = f.toBase(hand).eigen();
  return {handBase, f.toBase(modelForce(coupling(), f.k, hand)).eigen(),
          coupling().visualOnly ? Vec3::Zero() : Vec3(-handBase)};
}

}  // namespace hemiroll::physics
