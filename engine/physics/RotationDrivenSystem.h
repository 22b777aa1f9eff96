#pragma once
// The force-driven model of ForceDrivenSystem.h, the same physics, with the
// orientation integrated as a quaternion (BodyRotation.h says why) and the
// dynamics written in the base frame: 13 states, no trigonometry and no
// division by cos v_o in an evaluation. Convert at the boundary with
// toRotationState() / toContactState(); everything else (inputs, energy,
// events) matches the 12-state model.

#include <string_view>

#include "engine/physics/BodyRotation.h"
#include "engine/physics/ForceInput.h"
#include "engine/physics/OdeSystem.h"

namespace hemiroll::physics {

class RotationDrivenSystem final : public OdeSystem<13> {
 public:
  explicit RotationDrivenSystem(const HemisphereParams& params, const DomainLimits& limits = {});

  // Input modes (ForceInput.h). The default is free motion (no external force).
  void setFree() { input_.setFree(); }
  void setFaceForce(const Vec2& f) { input_.setFaceForce(f); }
  void setCoupling(const CouplingDef& def, const ProxyTrajectory& proxy) { input_.setCoupling(def, proxy); }
  void setCoupling(const CouplingDef& def) { input_.setCoupling(def); }
  void holdProxy(const ProxyPose& pose) { input_.holdProxy(pose); }

  void derivative(double t, const RotationState& x, RotationState& dxdt) const override;
  // The same margins as the 12-state model: cos(tilt) = k_z needs no angles.
  DomainMargins margins(double t, const RotationState& x) const override;
  bool autonomous() const override { return input_.autonomous(); }
  unsigned long long inputRevision() const override { return input_.revision(); }

  const RollingDynamics& dynamics() const { return dynamics_; }
  const DomainLimits& limits() const { return limits_; }

 private:
  Real3 inputForce(const RollingGeometryIn<BodyFrame>& g, double t, const RotationState& x,
                   const Real3& omega) const;

  RollingDynamics dynamics_;
  DomainLimits limits_;
  double cosMaxTilt_;
  ForceInput input_;
};

// How a force-driven run carries the orientation: the paper's contact angles
// (12 states, ForceDrivenSystem) or a quaternion (13 states, this class).
enum class OrientationForm { ContactAngles, Quaternion };
const char* orientationFormName(OrientationForm form);  // "angles", "quaternion"
bool parseOrientationForm(std::string_view name, OrientationForm& out);

Quaternion quaternionOf(const RotationState& x);
RotationState toRotationState(const ForceDrivenState& x);
// psi on the branch nearest psiNear (pass the previous value along a run).
ForceDrivenState toContactState(const RotationState& x, double psiNear);

}  // namespace hemiroll::physics
