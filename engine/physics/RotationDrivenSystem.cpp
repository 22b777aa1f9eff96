#include "engine/physics/RotationDrivenSystem.h"

#include <cmath>

namespace hemiroll::physics {

using namespace rotation_slot;

Quaternion quaternionOf(const RotationState& x) { return {x[q_w], x[q_x], x[q_y], x[q_z]}; }

const char* orientationFormName(OrientationForm form) {
  return form == OrientationForm::Quaternion ? "quaternion" : "angles";
}

bool parseOrientationForm(std::string_view name, OrientationForm& out) {
  if (name == "angles") out = OrientationForm::ContactAngles;
  else if (name == "quaternion") out = OrientationForm::Quaternion;
  else return false;
  return true;
}

RotationDrivenSystem::RotationDrivenSystem(const HemisphereParams& params, const DomainLimits& limits)
    : dynamics_(params), limits_(limits), cosMaxTilt_(std::cos(limits.maxTilt)) {}

Real3 RotationDrivenSystem::inputForce(const RollingGeometryIn<BodyFrame>& g, double t, const RotationState& x,
                                       const Real3& omega) const {
  switch (input_.mode()) {
    case ForceInput::Mode::Free: return {0.0, 0.0, 0.0};
    case ForceInput::Mode::FaceForce: return g.frame.inPlane(Real2::from(input_.faceForce()));
    case ForceInput::Mode::Coupling: {
      const Real3 centre{x[u_a], x[v_a], dynamics_.constants().params.radius};
      const Real3 hand = input_.handForce(t, g.frame.k, centre, g.rhoP, cross(omega, g.lever) + g.rhoPDot,
                                          [](const Real3& v) { return v; });
      return modelForce(input_.coupling(), g.frame.k, hand);
    }
  }
  return {0.0, 0.0, 0.0};
}

// flatten: the whole evaluation compiled as one function (geometry, input
// force, the 3x3 solve). Left to GCC's size limits, parts of it stay
// out of line and pass their results through memory (docs/PERFORMANCE.md).
[[gnu::flatten]] void RotationDrivenSystem::derivative(double t, const RotationState& x, RotationState& dxdt) const {
  const double radius = dynamics_.constants().params.radius;
  const Quaternion q = quaternionOf(x);
  const auto g = makeGeometry(dynamics_.constants(), makeBodyFrame(q), Real2{x[x_p], x[y_p]},
                              Real2{x[xd_p], x[yd_p]});
  const Real3 omega{x[w_x], x[w_y], x[w_z]};
  const Real3 force = inputForce(g, t, x, omega);

  const BodyAcceleration a = dynamics_.bodyAcceleration(g, omega, dot(g.frame.k, force));
  const Real2 pDDot = dynamics_.pointAcceleration(g, a, g.frame.toFace(force));
  const Quaternion qDot = quaternionRate(q, omega);
  dxdt[x_p] = x[xd_p];
  dxdt[y_p] = x[yd_p];
  dxdt[xd_p] = pDDot.x;
  dxdt[yd_p] = pDDot.y;
  dxdt[w_x] = a.omegaDot.x;
  dxdt[w_y] = a.omegaDot.y;
  dxdt[w_z] = a.omegaDot.z;
  dxdt[u_a] = radius * omega.y;  // no slip, eq. (11)
  dxdt[v_a] = -radius * omega.x;
  dxdt[q_w] = qDot.w;
  dxdt[q_x] = qDot.x;
  dxdt[q_y] = qDot.y;
  dxdt[q_z] = qDot.z;
}

DomainMargins RotationDrivenSystem::margins(double, const RotationState& x) const {
  const double radius = dynamics_.constants().params.radius;
  const double cosTilt = makeBodyFrame(quaternionOf(x)).k.z;
  return {cosTilt - cosMaxTilt_,
          limits_.maxPointRadius * radius - std::sqrt(x[x_p] * x[x_p] + x[y_p] * x[y_p])};
}

RotationState toRotationState(const ForceDrivenState& x) {
  RotationState r;
  r.head<9>() = x.head<9>();
  const Quaternion q = quaternionFromContactAngles(x[force_slot::u_o], x[force_slot::v_o], x[force_slot::psi]);
  r[q_w] = q.w;
  r[q_x] = q.x;
  r[q_y] = q.y;
  r[q_z] = q.z;
  return r;
}

ForceDrivenState toContactState(const RotationState& x, double psiNear) {
  ForceDrivenState c;
  c.head<9>() = x.head<9>();
  const ContactAngles a = contactAnglesFromQuaternion(quaternionOf(x), psiNear);
  c[force_slot::u_o] = a.u_o;
  c[force_slot::v_o] = a.v_o;
  c[force_slot::psi] = a.psi;
  return c;
}

}  // namespace hemiroll::physics
