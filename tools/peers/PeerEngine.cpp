#include "tools/peers/PeerEngine.h"

#include <cmath>
#include <cstdio>
#include <exception>

namespace hemiroll::tools::peers {

namespace {

bool finitePose(const Pose& p) {
  return p.faceCentre.allFinite() && p.rotation.allFinite() && p.omega.allFinite() && p.point.allFinite();
}

// Where the model itself ends (tilt past 90 degrees, the point off the face)
// or the engine has blown up: the reason, or nullptr inside. Checked after
// every step, so that an engine running away is stopped before its own
// asserts abort the process (ODE's do).
const char* outsideModel(const PeerScene& scene, const Pose& p) {
  if (!finitePose(p)) return "the state is not finite";
  if (p.rotation(2, 2) <= 0.0) return "tilted past 90 degrees";
  const Vec3 arm = p.rotation.transpose() * (p.point - p.faceCentre);
  if (arm.head<2>().norm() >= scene.params.radius || std::abs(arm.z()) >= scene.params.radius)
    return "the point left the face";
  if (std::abs(p.faceCentre.z() - scene.params.radius) >= 0.5 * scene.params.radius)
    return "the sphere left the plane";
  return nullptr;
}

// The hand that carries the prescribed point, as the model has it: an
// external force in the face plane (nothing pushes back on the shell in that
// plane; physics-notes.md), not a slide-joint motor, whose reaction on the
// shell would make a different system. It is a servo: the acceleration the
// point needs on its path, from the bodies' state (the shell's accelerations
// by backward differences over the last step), plus a critically damped
// correction with omega h = 1/4, stable for every engine's step.
class PrescribedHand {
 public:
  PrescribedHand(const PeerScene& scene, double timestep)
      : scene_(scene), h_(timestep), omega_(0.25 / timestep) {}

  Vec3 force(const Pose& pose, double t) {
    const Mat3& R = pose.rotation;
    const Vec3 arm = pose.point - pose.faceCentre;
    const Vec3 relativeVelocity = pose.pointVelocity - pose.faceCentreVelocity - pose.omega.cross(arm);
    const Vec2 p = (R.transpose() * arm).head<2>();
    const Vec2 pDot = (R.transpose() * relativeVelocity).head<2>();
    const physics::MassPointTrajectory::Sample want = scene_.trajectory->at(t);
    const Vec2 aRelative = want.pDDot + omega_ * omega_ * (want.p - p) + 2.0 * omega_ * (want.pDot - pDot);
    Vec3 omegaDot = Vec3::Zero(), centreAcceleration = Vec3::Zero();
    if (havePrevious_) {
      omegaDot = (pose.omega - previous_.omega) / h_;
      centreAcceleration = (pose.faceCentreVelocity - previous_.faceCentreVelocity) / h_;
    }
    previous_ = pose;
    havePrevious_ = true;
    const Vec3 a = centreAcceleration + omegaDot.cross(arm) + pose.omega.cross(pose.omega.cross(arm)) +
                   2.0 * pose.omega.cross(R * Vec3(pDot.x(), pDot.y(), 0.0)) +
                   R * Vec3(aRelative.x(), aRelative.y(), 0.0);
    const Vec3 gravity(0.0, 0.0, -scene_.params.gravity);
    const Vec3 total = scene_.params.pointMass * (a - gravity);
    const Vec3 normal = R.col(2);
    return total - normal * normal.dot(total);  // the face carries the normal part
  }

 private:
  const PeerScene& scene_;
  double h_, omega_;
  Pose previous_;
  bool havePrevious_ = false;
};

}  // namespace

RunResult runPeer(const PeerEngine& engine, const PeerScene& scene, const std::string& setting, double timestep) {
  RunResult r;
  r.engine = engine.name();
  r.setting = setting;
  r.step = timestep;
  std::unique_ptr<PeerWorld> world;
  try {
    world = engine.build(scene, setting, timestep, r.failure);
  } catch (const std::exception& e) {
    r.failure = e.what();
  }
  if (!world) return r;

  const int intervals = static_cast<int>(std::lround(scene.horizon / kSampleInterval));
  const long perSample = std::lround(kSampleInterval / timestep);
  r.samples.reserve(intervals + 1);
  Pose pose = world->pose();  // read once per step, for the drive and the check
  r.samples.push_back(sampleOf(scene, pose, 0.0));
  PrescribedHand hand(scene, timestep);
  const double t0 = cpuNow();
  long k = 0;
  for (int i = 1; i <= intervals && r.failure.empty(); ++i) {
    for (long j = 0; j < perSample; ++j, ++k) {
      // The same right-hand conditions for every engine: the drive is read
      // off the bodies at the start of the step and held over it.
      if (scene.drive == PointDrive::Tether && !world->ownsTether()) {
        world->setPointForce(scene.tetherStiffness * (scene.proxy - pose.point));
      } else if (scene.drive == PointDrive::Prescribed) {
        world->setPointForce(hand.force(pose, static_cast<double>(k) * timestep));
      }
      try {
        world->step();
        pose = world->pose();
        if (const char* why = outsideModel(scene, pose)) r.failure = why;
      } catch (const std::exception& e) {  // an engine's fatal error, turned into an exception
        r.failure = e.what();
      }
      if (!r.failure.empty()) {
        char when[64];
        std::snprintf(when, sizeof when, " at t = %.4f s", static_cast<double>(k + 1) * timestep);
        r.failure += when;
        r.samples.clear();
        break;
      }
    }
    if (r.failure.empty()) r.samples.push_back(sampleOf(scene, pose, i * kSampleInterval));
  }
  r.cpuSeconds = cpuNow() - t0;
  return r;
}

}  // namespace hemiroll::tools::peers
