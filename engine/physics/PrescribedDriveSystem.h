#pragma once
// The 8-state prescribed drive, eqs. (46)-(48): the mass point follows a
// given trajectory p(t) exactly, and the force that makes it do so is
// recovered from eq. (46) afterwards.

#include "engine/physics/OdeSystem.h"
#include "engine/physics/RollingDynamics.h"

namespace hemiroll::physics {

class MassPointTrajectory {
 public:
  struct Sample {
    Vec2 p, pDot, pDDot;  // [m], [m/s], [m/s^2], face coordinates
  };
  virtual ~MassPointTrajectory() = default;
  virtual Sample at(double t) const = 0;
};

// The 8 rates of eq. (47) at x for the mass point at p moving at pDot (face
// coordinates), over doubles or lanes (BatchedRk4.h):
// PrescribedDriveSystem::derivative and the batched integrator both evaluate
// the model here. p'' does not enter the hemisphere's dynamics.
template <class T>
inline void prescribedRatesOf(const MassConstantsOf<T>& c, const Real2Of<T>& p, const Real2Of<T>& pDot, const T* x,
                              T* dxdt) {
  using namespace body_slot;
  const RollingGeometryIn<HeadingFrameOf<T>> g =
      geometryIn(c.radius, makeHeadingFrame(x[u_o], x[v_o], x[psi]), p, pDot);
  const HeadingFrameOf<T>& f = g.frame;
  const Real3Of<T> omega{x[w_x], x[w_y], x[w_z]};
  const Real3Of<T> omegaH = f.toHeading(omega);
  const Real3Of<T> omegaDot = f.toBase(bodyAccelerationOf(c, g, omegaH, broadcast<T>(0.0)).omegaDot);
  const ContactRatesOf<T> rates = contactRates(f.cv, f.sv, f.cpsi, f.spsi, c.radius, omega);
  static_assert(w_x == 0 && psi == 7, "the body state is w, then the contact coordinates");
  writeBodyRates(dxdt, omegaDot, rates);
}

class PrescribedDriveSystem final : public OdeSystem<8> {
 public:
  PrescribedDriveSystem(const HemisphereParams& params, const MassPointTrajectory& trajectory,
                        const DomainLimits& limits = {});

  void derivative(double t, const BodyState& x, BodyState& dxdt) const override;
  DomainMargins margins(double t, const BodyState& x) const override;
  // The margins' answer, without their trigonometry away from the edges.
  DomainEvent domainEvent(double t, const BodyState& x) const override;
  // The same answer given the trajectory's p at t (the lanes computed it
  // while stepping: BatchedRk4.h), without evaluating the trajectory again.
  DomainEvent domainEventWith(double t, const BodyState& x, const Vec2& p) const;

  // f of eq. (46): the in-face force on the mass point that realises p''(t).
  Vec2 drivingForce(double t, const BodyState& x) const;
  // The same instant as a 12-state vector, with p and p' from the trajectory.
  ForceDrivenState fullState(double t, const BodyState& x) const;

  const RollingDynamics& dynamics() const { return dynamics_; }
  // domainEvent's trigonometry-free test (the lanes run it too: RoseBatch).
  const InteriorCheck& interior() const { return interior_; }

 private:
  RollingDynamics dynamics_;
  const MassPointTrajectory& trajectory_;
  DomainLimits limits_;
  double cosMaxTilt_;
  InteriorCheck interior_;
};

}  // namespace hemiroll::physics
