#pragma once
// The 12-state force-driven model, eq. (31) with the corrected u_o row: the
// mass point is pushed by an external force (the hand, through a coupling),
// and nothing pushes back on the hemisphere in the face plane.

#include "engine/physics/ForceInput.h"
#include "engine/physics/OdeSystem.h"

namespace hemiroll::physics {

class ForceDrivenSystem final : public OdeSystem<12> {
 public:
  explicit ForceDrivenSystem(const HemisphereParams& params, const DomainLimits& limits = {});

  // Input modes (ForceInput.h). The default is free motion (no external force).
  void setFree() { input_.setFree(); }
  void setFaceForce(const Vec2& f) { input_.setFaceForce(f); }
  void setCoupling(const CouplingDef& def, const ProxyTrajectory& proxy) { input_.setCoupling(def, proxy); }
  void setCoupling(const CouplingDef& def) { input_.setCoupling(def); }
  void holdProxy(const ProxyPose& pose) { input_.holdProxy(pose); }

  void derivative(double t, const ForceDrivenState& x, ForceDrivenState& dxdt) const override;
  DomainMargins margins(double t, const ForceDrivenState& x) const override;
  // The margins' answer, without their trigonometry away from the edges.
  DomainEvent domainEvent(double t, const ForceDrivenState& x) const override;
  // Free motion, a constant face force and a held proxy are autonomous; a
  // proxy trajectory is not.
  bool autonomous() const override { return input_.autonomous(); }
  unsigned long long inputRevision() const override { return input_.revision(); }

  // The force the model receives on the mass point at (t, x), base frame [N].
  Vec3 externalForce(double t, const ForceDrivenState& x) const;
  // The coupling's forces at (t, x); zero forces unless a coupling is set.
  CouplingForces couplingForces(double t, const ForceDrivenState& x) const;

  const RollingDynamics& dynamics() const { return dynamics_; }
  const DomainLimits& limits() const { return limits_; }
  bool coupled() const { return input_.mode() == ForceInput::Mode::Coupling; }
  const CouplingDef& coupling() const { return input_.coupling(); }

 private:
  // Both in the heading frame of g, for angular velocity omegaH (heading frame).
  Real3 inputForce(const RollingGeometry& g, double t, const ForceDrivenState& x, const Real3& omegaH) const;
  Real3 handForceAt(const RollingGeometry& g, double t, const ForceDrivenState& x, const Real3& omegaH) const;

  RollingDynamics dynamics_;
  DomainLimits limits_;
  double cosMaxTilt_;
  InteriorCheck interior_;
  ForceInput input_;
};

// Geometry of a 12-state vector, heading frame (shared by the system, energy
// and couplings).
RollingGeometry geometryOf(const ModelConstants& c, const ForceDrivenState& x);

// The 12 rates of eq. (31) at x, over doubles or lanes (BatchedRk4.h):
// ForceDrivenSystem::derivative and the batched integrator both evaluate the
// model here. inputForce(g, omegaH) gives the force on the mass point in the
// heading frame of g, for angular velocity omegaH in that frame.
template <class T, class InputForce>
inline void forceDrivenRatesOf(const MassConstantsOf<T>& c, const T* x, T* dxdt, const InputForce& inputForce) {
  using namespace force_slot;
  const RollingGeometryIn<HeadingFrameOf<T>> g = geometryIn(
      c.radius, makeHeadingFrame(x[u_o], x[v_o], x[psi]), Real2Of<T>{x[x_p], x[y_p]}, Real2Of<T>{x[xd_p], x[yd_p]});
  const HeadingFrameOf<T>& f = g.frame;
  const Real3Of<T> omega{x[w_x], x[w_y], x[w_z]};
  const Real3Of<T> omegaH = f.toHeading(omega);
  const Real3Of<T> force = inputForce(g, omegaH);

  const BodyAccelerationOf<T> a = bodyAccelerationOf(c, g, omegaH, dot(f.k, force));
  const Real2Of<T> pDDot = pointAccelerationOf(c, g, a, f.toFace(force));
  const Real3Of<T> omegaDot = f.toBase(a.omegaDot);

  const ContactRatesOf<T> rates = contactRates(f.cv, f.sv, f.cpsi, f.spsi, c.radius, omega);
  dxdt[x_p] = x[xd_p];
  dxdt[y_p] = x[yd_p];
  dxdt[xd_p] = pDDot.x;
  dxdt[yd_p] = pDDot.y;
  static_assert(w_x == body && psi == body + 7, "slots 4..11 are the body state");
  writeBodyRates(dxdt + body, omegaDot, rates);
}

}  // namespace hemiroll::physics
