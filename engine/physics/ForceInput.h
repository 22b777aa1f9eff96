#pragma once
// What pushes the mass point of a force-driven model: nothing, a constant
// in-face force, or a coupling to a haptic proxy (a trajectory known in
// advance, or a pose held between servo ticks). Shared by the two
// formulations of the force-driven model (contact angles: ForceDrivenSystem;
// quaternion: RotationDrivenSystem), so that both take the same inputs and
// wake a sleeping stepper on the same changes.

#include "engine/physics/ForceCoupling.h"

namespace hemiroll::physics {

// The proxy as a continuous function of time, for headless runs where the
// input is known in advance (it is evaluated at every integrator stage).
class ProxyTrajectory {
 public:
  virtual ~ProxyTrajectory() = default;
  virtual ProxyPose at(double t) const = 0;
};

// F_h for a proxy at proxyPosition moving at proxyVelocity (base frame), in
// the frame that toFrame() turns the base frame into: k is the face normal
// and rhoP the mass point from the face centre in that frame, centre the
// sphere centre in the base frame, pointVelocity the mass point's absolute
// velocity in that frame. Over doubles or lanes (BatchedRk4.h).
template <class T, class ToFrame>
inline Real3Of<T> handForceFromProxy(const CouplingLawOf<T>& law, const Real3Of<T>& k, const Real3Of<T>& centre,
                                     const Real3Of<T>& rhoP, const Real3Of<T>& pointVelocity,
                                     const Real3Of<T>& proxyPosition, const Real3Of<T>& proxyVelocity,
                                     ToFrame toFrame) {
  const Real3Of<T> dr = toFrame(centre - proxyPosition) + rhoP;
  const Real3Of<T> dv = pointVelocity - toFrame(proxyVelocity);
  return handForceOf(law, k, dr, dv);
}

class ForceInput {
 public:
  enum class Mode { Free, FaceForce, Coupling };

  void setFree();
  void setFaceForce(const Vec2& f);  // constant in-face force f [N], face coordinates
  void setCoupling(const CouplingDef& def, const ProxyTrajectory& proxy);
  // Coupling to a proxy held constant until the next call (zero-order hold,
  // as a device sampled once per servo tick gives it).
  void setCoupling(const CouplingDef& def);
  // Holding the same pose again (bitwise) is no change: it does not wake a
  // sleeping stepper.
  void holdProxy(const ProxyPose& pose);

  Mode mode() const { return mode_; }
  const Vec2& faceForce() const { return faceForce_; }
  const CouplingDef& coupling() const { return coupling_; }
  ProxyPose proxyAt(double t) const { return proxyFn_ ? proxyFn_->at(t) : heldProxy_; }
  // Free motion, a constant face force and a held proxy do not depend on t.
  bool autonomous() const { return mode_ != Mode::Coupling || proxyFn_ == nullptr; }
  // Changes whenever the input changes.
  unsigned long long revision() const { return revision_; }

  // F_h on the mass point (coupling mode), in a frame that shares the
  // vertical with the base frame and is turned from it by toFrame(): k is
  // the face normal and rhoP the mass point from the face centre in that
  // frame, centre the sphere centre in the base frame, pointVelocity the
  // mass point's absolute velocity in that frame.
  template <class ToFrame>
  Real3 handForce(double t, const Real3& k, const Real3& centre, const Real3& rhoP, const Real3& pointVelocity,
                  ToFrame toFrame) const {
    const ProxyPose proxy = proxyAt(t);
    return handForceFromProxy(couplingLawOf(coupling_), k, centre, rhoP, pointVelocity,
                              Real3::from(proxy.position), Real3::from(proxy.velocity), toFrame);
  }

 private:
  Mode mode_ = Mode::Free;
  Vec2 faceForce_ = Vec2::Zero();
  CouplingDef coupling_;
  const ProxyTrajectory* proxyFn_ = nullptr;
  ProxyPose heldProxy_;
  unsigned long long revision_ = 0;
};

}  // namespace hemiroll::physics
