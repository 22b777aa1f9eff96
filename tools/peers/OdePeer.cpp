// ODE 0.16 (Debian's libode-dev, double precision): maximal coordinates. The
// shell is a body with a sphere geom offset 3R/8 above its centre of mass (ODE
// wants the body frame at the centre of mass); ODE has no two-axis slide
// joint, so the point hangs on two sliders through a carrier body of 1e-6 of
// the point's mass (its one-direction mass error, 1e-6 relative, is far below
// every error measured here).

#include <ode/ode.h>

#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>

#include "tools/peers/PeerEngine.h"

namespace hemiroll::tools::peers {

namespace {

constexpr double kCarrierMassRatio = 1e-6;

struct Setting {
  bool quickStep = true;        // dWorldQuickStep (iterative) or dWorldStep (direct LCP)
  int quickIterations = 20;     // ODE's default
  double erp = 0.2, cfm = 1e-10;  // ODE's defaults in double precision
  bool pyramid = false;         // dContactApprox1: friction pyramid scaled by the normal force
  double mu = dInfinity;        // the manual: dInfinity "results in a contact that never slips"
};

Setting settingNamed(const std::string& name) {
  Setting s;
  if (name == "tuned") {
    s.quickStep = false;  // the exact LCP solve, which the manual recommends for accuracy
    s.erp = 0.9;
    s.cfm = 1e-12;
  } else if (name == "tuned_pyramid") {
    s.quickStep = false;
    s.erp = 0.9;
    s.cfm = 1e-12;
    s.pyramid = true;
    s.mu = 10.0;
  }
  return s;
}

// ODE's error and debug handlers abort the process by default; the study
// turns them into a failed run instead (ODE is C++ inside, built with
// exceptions).
[[noreturn]] void throwOdeError(int code, const char* message, va_list args) {
  char text[256];
  std::vsnprintf(text, sizeof text, message, args);
  throw std::runtime_error("ODE error " + std::to_string(code) + ": " + text);
}

void initialiseOdeOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dSetErrorHandler(throwOdeError);
    dSetDebugHandler(throwOdeError);
  });
}

class OdeWorld final : public PeerWorld {
 public:
  OdeWorld(const PeerScene& scene, const Setting& s, double timestep) : s_(s), h_(timestep), radius_(scene.params.radius) {
    initialiseOdeOnce();
    world_ = dWorldCreate();
    space_ = dSimpleSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);
    dWorldSetGravity(world_, 0, 0, -scene.params.gravity);
    dWorldSetERP(world_, s.erp);
    dWorldSetCFM(world_, s.cfm);
    dWorldSetQuickStepNumIterations(world_, s.quickIterations);
    plane_ = dCreatePlane(space_, 0, 0, 1, 0);

    const physics::HemisphereParams& p = scene.params;
    const Pose start = poseOf(p, scene.x0);
    const Vec3 comArm = start.rotation * shellComOffset(p.radius);
    dMatrix3 rot;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) rot[4 * r + c] = start.rotation(r, c);
      rot[4 * r + 3] = 0;
    }

    shell_ = dBodyCreate(world_);
    const Vec3 I = shellPrincipalInertia(p);
    dMass m;
    const double rider = riderInertia(p);  // half on the carrier, half on the point
    dMassSetParameters(&m, p.shellMass, 0, 0, 0, I.x() - rider, I.y() - rider, I.z() - rider, 0, 0, 0);
    dBodySetMass(shell_, &m);
    const Vec3 com = start.faceCentre + comArm;
    const Vec3 comVelocity = start.faceCentreVelocity + start.omega.cross(comArm);
    dBodySetPosition(shell_, com.x(), com.y(), com.z());
    dBodySetRotation(shell_, rot);
    dBodySetLinearVel(shell_, comVelocity.x(), comVelocity.y(), comVelocity.z());
    dBodySetAngularVel(shell_, start.omega.x(), start.omega.y(), start.omega.z());
    sphere_ = dCreateSphere(space_, p.radius);
    dGeomSetBody(sphere_, shell_);
    dGeomSetOffsetPosition(sphere_, 0, 0, 3.0 * p.radius / 8.0);

    // Carrier and point start where the point is, moving with it.
    const Vec3 xAxis = start.rotation.col(0), yAxis = start.rotation.col(1);
    const double xd = scene.x0[physics::force_slot::xd_p];
    const Vec3 carried = start.faceCentreVelocity + start.omega.cross(start.point - start.faceCentre);
    carrier_ = makeBody(kCarrierMassRatio * p.pointMass, 0.5 * rider, start.point, rot, carried + xd * xAxis, start.omega);
    point_ = makeBody(p.pointMass, 0.5 * rider, start.point, rot, start.pointVelocity, start.omega);

    slideX_ = dJointCreateSlider(world_, nullptr);
    dJointAttach(slideX_, shell_, carrier_);
    dJointSetSliderAxis(slideX_, xAxis.x(), xAxis.y(), xAxis.z());
    slideY_ = dJointCreateSlider(world_, nullptr);
    dJointAttach(slideY_, carrier_, point_);
    dJointSetSliderAxis(slideY_, yAxis.x(), yAxis.y(), yAxis.z());
  }
  ~OdeWorld() override {
    dJointGroupDestroy(contacts_);
    dSpaceDestroy(space_);
    dWorldDestroy(world_);
  }

  Pose pose() const override {
    Pose pose;
    const dReal* R = dBodyGetRotation(shell_);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) pose.rotation(r, c) = R[4 * r + c];
    const dReal* com = dBodyGetPosition(shell_);
    const dReal* v = dBodyGetLinearVel(shell_);
    const dReal* w = dBodyGetAngularVel(shell_);
    pose.omega = Vec3(w[0], w[1], w[2]);
    const Vec3 toCentre = pose.rotation * -shellComOffset(radius_);
    pose.faceCentre = Vec3(com[0], com[1], com[2]) + toCentre;
    pose.faceCentreVelocity = Vec3(v[0], v[1], v[2]) + pose.omega.cross(toCentre);
    const dReal* pp = dBodyGetPosition(point_);
    const dReal* pv = dBodyGetLinearVel(point_);
    pose.point = Vec3(pp[0], pp[1], pp[2]);
    pose.pointVelocity = Vec3(pv[0], pv[1], pv[2]);
    return pose;
  }
  void setPointForce(const Vec3& f) override { dBodyAddForce(point_, f.x(), f.y(), f.z()); }
  void step() override {
    dContactGeom geom;
    if (dCollide(sphere_, plane_, 1, &geom, sizeof(dContactGeom)) > 0) {
      dContact contact{};
      contact.geom = geom;
      contact.surface.mode = s_.pyramid ? dContactApprox1 : 0;
      contact.surface.mu = s_.mu;
      dJointID j = dJointCreateContact(world_, contacts_, &contact);
      dJointAttach(j, shell_, nullptr);
    }
    if (s_.quickStep) {
      dWorldQuickStep(world_, h_);
    } else {
      dWorldStep(world_, h_);
    }
    dJointGroupEmpty(contacts_);
  }

 private:
  dBodyID makeBody(double mass, double inertia, const Vec3& at, const dMatrix3 rot, const Vec3& velocity, const Vec3& omega) {
    dBodyID b = dBodyCreate(world_);
    dMass m;
    dMassSetParameters(&m, mass, 0, 0, 0, inertia, inertia, inertia, 0, 0, 0);
    dBodySetMass(b, &m);
    dBodySetPosition(b, at.x(), at.y(), at.z());
    dBodySetRotation(b, rot);
    dBodySetLinearVel(b, velocity.x(), velocity.y(), velocity.z());
    dBodySetAngularVel(b, omega.x(), omega.y(), omega.z());
    return b;
  }

  Setting s_;
  double h_;
  double radius_;
  dWorldID world_;
  dSpaceID space_;
  dJointGroupID contacts_;
  dBodyID shell_, carrier_, point_;
  dGeomID plane_, sphere_;
  dJointID slideX_, slideY_;
};

class OdeEngine final : public PeerEngine {
 public:
  std::string name() const override { return "ode"; }
  std::string version() const override {
    initialiseOdeOnce();
    return dCheckConfiguration("ODE_double_precision") ? "0.16, double precision" : "0.16, single precision";
  }
  std::vector<PeerSetting> settings() const override {
    return {{"default", "dWorldQuickStep, 20 iterations, ERP 0.2, CFM 1e-10, mu = dInfinity (never slips)"},
            {"tuned", "dWorldStep (direct LCP), ERP 0.9, CFM 1e-12, mu = dInfinity"},
            {"tuned_pyramid", "as tuned, friction pyramid (dContactApprox1) with mu 10"}};
  }
  std::unique_ptr<PeerWorld> build(const PeerScene& scene, const std::string& setting, double timestep,
                                   std::string&) const override {
    return std::make_unique<OdeWorld>(scene, settingNamed(setting), timestep);
  }
};

}  // namespace

std::unique_ptr<PeerEngine> makeOdeEngine() { return std::make_unique<OdeEngine>(); }

}  // namespace hemiroll::tools::peers
