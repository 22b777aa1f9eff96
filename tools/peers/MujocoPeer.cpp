// MuJoCo 2.2.2 (Debian's libmujoco-dev): the shell is a body on a free joint
// with a sphere geom, the point a child body on two slide joints. Generalised
// coordinates: the point cannot drift off the face plane, only the contact is
// soft.

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>

#include <cstdio>
#include <cstring>
#include <sstream>

#include "tools/peers/PeerEngine.h"

namespace hemiroll::tools::peers {

namespace {

struct Setting {
  std::string integrator = "Euler";
  std::string cone = "pyramidal";
  double friction = 1.0;  // MuJoCo's default sliding friction
  double impratio = 1.0;
  int noslipIterations = 0;
  std::string solref = "0.02 1";  // the default (time constant 20 ms)
  std::string solimp = "0.9 0.95 0.001";
  int iterations = 100;
  double tolerance = 1e-8;
};

Setting settingNamed(const std::string& name, double timestep) {
  Setting s;
  if (name == "tuned") {
    // The documentation's recipe for contacts that do not slip: elliptic
    // cones with a high impratio, the noslip post-processor, the stiffest
    // stable time constant (2 time steps) and a hard impedance.
    s.cone = "elliptic";
    s.friction = 2.0;
    s.impratio = 100.0;
    s.noslipIterations = 50;
    std::ostringstream ref;
    ref.precision(17);
    ref << 2.0 * timestep << " 1";
    s.solref = ref.str();
    s.solimp = "0.99 0.999 0.0001";
    s.tolerance = 1e-12;
  } else if (name == "tuned_rk4") {
    s = settingNamed("tuned", timestep);
    s.integrator = "RK4";
  }
  return s;
}

class MujocoWorld final : public PeerWorld {
 public:
  MujocoWorld(mjModel* m, mjData* d) : m_(m), d_(d) {}
  ~MujocoWorld() override {
    mj_deleteData(d_);
    mj_deleteModel(m_);
  }

  Pose pose() const override {
    Pose p;
    const mjtNum* xmat = d_->xmat + 9 * kShell;  // row-major
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) p.rotation(r, c) = xmat[3 * r + c];
    p.faceCentre = Vec3(d_->qpos[0], d_->qpos[1], d_->qpos[2]);
    p.faceCentreVelocity = Vec3(d_->qvel[0], d_->qvel[1], d_->qvel[2]);
    p.omega = p.rotation * Vec3(d_->qvel[3], d_->qvel[4], d_->qvel[5]);  // free joint: body frame
    const Vec3 arm = p.rotation * Vec3(d_->qpos[7], d_->qpos[8], 0.0);
    p.point = p.faceCentre + arm;
    p.pointVelocity = p.faceCentreVelocity + p.omega.cross(arm) + p.rotation * Vec3(d_->qvel[6], d_->qvel[7], 0.0);
    return p;
  }
  void setPointForce(const Vec3& f) override {
    mjtNum* x = d_->xfrc_applied + 6 * kPoint;  // at the body's centre of mass, world frame
    x[0] = f.x();
    x[1] = f.y();
    x[2] = f.z();
  }
  bool ownsTether() const override { return true; }  // the tendon
  void step() override { mj_step(m_, d_); }

 private:
  static constexpr int kShell = 1, kPoint = 2;  // body ids (0 is the world)
  mjModel* m_;
  mjData* d_;
};

std::string modelXml(const PeerScene& scene, const Setting& s, double timestep) {
  const physics::HemisphereParams& p = scene.params;
  const Vec3 inertia = shellPrincipalInertia(p);
  const double R = p.radius;
  std::ostringstream x;
  x.precision(17);
  const std::string contact = " condim=\"3\" friction=\"" + std::to_string(s.friction) + " 0 0\" solref=\"" +
                              s.solref + "\" solimp=\"" + s.solimp + "\"";
  const double pointInertia = riderInertia(p);
  x << "<mujoco model=\"hemiroll_peer\">\n"
    << "<compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n"
    << "<option timestep=\"" << timestep << "\" gravity=\"0 0 " << -p.gravity << "\" integrator=\""
    << s.integrator << "\" cone=\""
    << s.cone << "\" impratio=\"" << s.impratio << "\" noslip_iterations=\"" << s.noslipIterations
    << "\" iterations=\"" << s.iterations << "\" tolerance=\"" << s.tolerance << "\" solver=\"Newton\"/>\n"
    << "<worldbody>\n"
    << "<geom name=\"floor\" type=\"plane\" size=\"0 0 1\"" << contact << "/>\n"
    << "<site name=\"proxy\" pos=\"" << scene.proxy.x() << " " << scene.proxy.y() << " " << scene.proxy.z()
    << "\"/>\n"
    << "<body name=\"shell\">\n<freejoint name=\"shell_free\"/>\n"
    << "<inertial pos=\"0 0 " << -3.0 * R / 8.0 << "\" mass=\"" << p.shellMass << "\" diaginertia=\""
    << inertia.x() - pointInertia << " " << inertia.y() - pointInertia << " " << inertia.z() - pointInertia
    << "\"/>\n"
    << "<geom name=\"sphere\" type=\"sphere\" size=\"" << R << "\"" << contact << "/>\n"
    << "<body name=\"point\">\n"
    << "<joint name=\"px\" type=\"slide\" axis=\"1 0 0\"/>\n<joint name=\"py\" type=\"slide\" axis=\"0 1 0\"/>\n"
    << "<inertial pos=\"0 0 0\" mass=\"" << p.pointMass << "\" diaginertia=\"" << pointInertia << " "
    << pointInertia << " " << pointInertia << "\"/>\n"
    << "<site name=\"point\"/>\n"
    << "</body>\n</body>\n</worldbody>\n";
  if (scene.drive == PointDrive::Tether) {
    // The spring as MuJoCo's own passive force (a spatial tendon of rest
    // length 0 from the proxy to the point), evaluated in every stage of its
    // integrator, rather than a force held over the step.
    x << "<tendon>\n<spatial stiffness=\"" << scene.tetherStiffness
      << "\" springlength=\"0\">\n<site site=\"proxy\"/>\n<site site=\"point\"/>\n</spatial>\n</tendon>\n";
  }
  x << "</mujoco>\n";
  return x.str();
}

class MujocoEngine final : public PeerEngine {
 public:
  std::string name() const override { return "mujoco"; }
  std::string version() const override { return mj_versionString(); }
  std::vector<PeerSetting> settings() const override {
    return {{"default", "MuJoCo's defaults: Euler, pyramidal cone, condim 3, friction 1, solref 0.02 1, no noslip"},
            {"tuned", "elliptic cone, impratio 100, friction 2, noslip_iterations 50, solref 2h 1, "
                      "solimp 0.99 0.999, Newton to 1e-12, Euler"},
            {"tuned_rk4", "as tuned, with MuJoCo's RK4 integrator"}};
  }

  std::unique_ptr<PeerWorld> build(const PeerScene& scene, const std::string& settingName, double timestep,
                                   std::string& error) const override {
    const Setting s = settingNamed(settingName, timestep);
    const std::string xml = modelXml(scene, s, timestep);
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    if (mj_makeEmptyFileVFS(&vfs, "peer.xml", static_cast<int>(xml.size())) != 0) {
      error = "MuJoCo: could not make the model file in memory";
      return nullptr;
    }
    std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "peer.xml")], xml.data(), xml.size());
    char message[1000] = "";
    mjModel* m = mj_loadXML("peer.xml", &vfs, message, sizeof message);
    mj_deleteVFS(&vfs);
    if (!m) {
      error = std::string("MuJoCo refused the model: ") + message;
      return nullptr;
    }
    mjData* d = mj_makeData(m);
    const Pose start = poseOf(scene.params, scene.x0);
    const Eigen::Quaterniond q(start.rotation);
    const Vec3 omegaBody = start.rotation.transpose() * start.omega;
    const mjtNum qpos[9] = {start.faceCentre.x(), start.faceCentre.y(), start.faceCentre.z(), q.w(), q.x(), q.y(), q.z(),
                            scene.x0[physics::force_slot::x_p], scene.x0[physics::force_slot::y_p]};
    const mjtNum qvel[8] = {start.faceCentreVelocity.x(), start.faceCentreVelocity.y(), start.faceCentreVelocity.z(),
                            omegaBody.x(), omegaBody.y(), omegaBody.z(),
                            scene.x0[physics::force_slot::xd_p], scene.x0[physics::force_slot::yd_p]};
    std::memcpy(d->qpos, qpos, sizeof qpos);
    std::memcpy(d->qvel, qvel, sizeof qvel);
    mj_forward(m, d);
    return std::make_unique<MujocoWorld>(m, d);
  }
};

}  // namespace

std::unique_ptr<PeerEngine> makeMujocoEngine() { return std::make_unique<MujocoEngine>(); }

}  // namespace hemiroll::tools::peers
