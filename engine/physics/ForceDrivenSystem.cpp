#include "engine/physics/ForceDrivenSystem.h"

#include <cmath>

namespace hemiroll::physics {

using namespace force_slot;

RollingGeometry geometryOf(const ModelConstants& c, const ForceDrivenState& x) {
  return makeGeometry(c, makeOrientation(x[u_o], x[v_o], x[psi]), x.segment<2>(x_p), x.segment<2>(xd_p));
}

ForceDrivenSystem::ForceDrivenSystem(const HemisphereParams& params, const DomainLimits& limits)
    : dynamics_(params), limits_(limits) {}

void ForceDrivenSystem::setFree() {
  input_ = Input::Free;
  proxyFn_ = nullptr;
}

void ForceDrivenSystem::setFaceForce(const Vec2& f) {
  input_ = Input::FaceForce;
  faceForce_ = f;
  proxyFn_ = nullptr;
}

void ForceDrivenSystem::setCoupling(const CouplingDef& def, const ProxyTrajectory& proxy) {
  input_ = Input::Coupling;
  coupling_ = def;
  proxyFn_ = &proxy;
}

void ForceDrivenSystem::setCoupling(const CouplingDef& def) {
  input_ = Input::Coupling;
  coupling_ = def;
  proxyFn_ = nullptr;
}

Vec3 ForceDrivenSystem::inputForce(const RollingGeometry& g, double t, const ForceDrivenState& x) const {
  switch (input_) {
    case Input::Free: return Vec3::Zero();
    case Input::FaceForce: return g.inPlane(faceForce_);
    case Input::Coupling: return couplingAt(g, t, x).modelForce;
  }
  return Vec3::Zero();
}

CouplingForces ForceDrivenSystem::couplingAt(const RollingGeometry& g, double t, const ForceDrivenState& x) const {
  const double radius = dynamics_.constants().params.radius;
  const PointKinematics point = pointKinematics(g, radius, x[u_a], x[v_a], x.segment<3>(w_x));
  return computeCoupling(coupling_, g, point, proxyAt(t));
}

void ForceDrivenSystem::derivative(double t, const ForceDrivenState& x, ForceDrivenState& dxdt) const {
  const ModelConstants& c = dynamics_.constants();
  const RollingGeometry g = geometryOf(c, x);
  const Vec3 omega = x.segment<3>(w_x);

  const Vec3 force = inputForce(g, t, x);

  const BodyAcceleration a = dynamics_.bodyAcceleration(g, omega, g.faceNormal.dot(force));
  const ContactRates rates = contactRates(g.orientation, c.params.radius, omega);

  dxdt.segment<2>(x_p) = x.segment<2>(xd_p);
  dxdt.segment<2>(xd_p) = dynamics_.pointAcceleration(g, a, g.toFace(force));
  dxdt.segment<3>(w_x) = a.omegaDot;
  dxdt[u_a] = rates.u_a;
  dxdt[v_a] = rates.v_a;
  dxdt[u_o] = rates.u_o;
  dxdt[v_o] = rates.v_o;
  dxdt[psi] = rates.psi;
}

DomainMargins ForceDrivenSystem::margins(double, const ForceDrivenState& x) const {
  const double radius = dynamics_.constants().params.radius;
  return {std::cos(x[u_o]) * std::cos(x[v_o]) - std::cos(limits_.maxTilt),
          limits_.maxPointRadius * radius - std::hypot(x[x_p], x[y_p])};
}

Vec3 ForceDrivenSystem::externalForce(double t, const ForceDrivenState& x) const {
  return inputForce(geometryOf(dynamics_.constants(), x), t, x);
}

CouplingForces ForceDrivenSystem::couplingForces(double t, const ForceDrivenState& x) const {
  const RollingGeometry g = geometryOf(dynamics_.constants(), x);
  if (input_ != Input::Coupling) return {Vec3::Zero(), inputForce(g, t, x), Vec3::Zero()};
  return couplingAt(g, t, x);
}

}  // namespace hemiroll::physics
