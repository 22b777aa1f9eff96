#pragma once
// The 12-state force-driven model, eq. (31) with the corrected u_o row: the
// mass point is pushed by an external force (the hand, through a coupling),
// and nothing pushes back on the hemisphere in the face plane.

#include "engine/physics/ForceCoupling.h"
#include "engine/physics/OdeSystem.h"

namespace hemiroll::physics {

// The proxy as a continuous function of time, for headless runs where the
// input is known in advance (it is evaluated at every integrator stage).
class ProxyTrajectory {
 public:
  virtual ~ProxyTrajectory() = default;
  virtual ProxyPose at(double t) const = 0;
};

class ForceDrivenSystem final : public OdeSystem<12> {
 public:
  explicit ForceDrivenSystem(const HemisphereParams& params, const DomainLimits& limits = {});

  // Input modes. The default is free motion (no external force).
  void setFree();
  void setFaceForce(const Vec2& f);  // constant in-face force f [N], face coordinates
  void setCoupling(const CouplingDef& def, const ProxyTrajectory& proxy);
  // Coupling to a proxy held constant until the next call (zero-order hold,
  // as a device sampled once per servo tick gives it).
  void setCoupling(const CouplingDef& def);
  // Holding the same pose again (bitwise) is no change: it does not wake a
  // sleeping stepper.
  void holdProxy(const ProxyPose& pose);

  void derivative(double t, const ForceDrivenState& x, ForceDrivenState& dxdt) const override;
  DomainMargins margins(double t, const ForceDrivenState& x) const override;
  // Free motion, a constant face force and a held proxy are autonomous; a
  // proxy trajectory is not.
  bool autonomous() const override { return input_ != Input::Coupling || proxyFn_ == nullptr; }
  unsigned long long inputRevision() const override { return inputRevision_; }

  // The force the model receives on the mass point at (t, x), base frame [N].
  Vec3 externalForce(double t, const ForceDrivenState& x) const;
  // The coupling's forces at (t, x); zero forces unless a coupling is set.
  CouplingForces couplingForces(double t, const ForceDrivenState& x) const;

  const RollingDynamics& dynamics() const { return dynamics_; }
  const DomainLimits& limits() const { return limits_; }
  bool coupled() const { return input_ == Input::Coupling; }
  const CouplingDef& coupling() const { return coupling_; }

 private:
  enum class Input { Free, FaceForce, Coupling };

  ProxyPose proxyAt(double t) const { return proxyFn_ ? proxyFn_->at(t) : heldProxy_; }
  // Both in the heading frame of g, for angular velocity omegaH (heading frame).
  Real3 inputForce(const RollingGeometry& g, double t, const ForceDrivenState& x, const Real3& omegaH) const;
  Real3 handForceAt(const RollingGeometry& g, double t, const ForceDrivenState& x, const Real3& omegaH) const;

  RollingDynamics dynamics_;
  DomainLimits limits_;
  double cosMaxTilt_;
  Input input_ = Input::Free;
  Vec2 faceForce_ = Vec2::Zero();
  CouplingDef coupling_;
  const ProxyTrajectory* proxyFn_ = nullptr;
  ProxyPose heldProxy_;
  unsigned long long inputRevision_ = 0;
};

// Geometry of a 12-state vector, heading frame (shared by the system, energy
// and couplings).
RollingGeometry geometryOf(const ModelConstants& c, const ForceDrivenState& x);

}  // namespace hemiroll::physics
