// Bullet 3.24 (Debian's libbullet-dev, the float64 build): maximal
// coordinates with the sequential-impulse solver. The shell is a rigid body
// with a compound shape (the sphere 3R/8 above its centre of mass: Bullet's
// body frame is the centre of mass); the point is a body on one
// btGeneric6DofSpring2Constraint that frees x and y of the face and locks the
// rest, so no carrier body is needed.

#include <btBulletDynamicsCommon.h>

#include <memory>

#include "tools/peers/PeerEngine.h"

namespace hemiroll::tools::peers {

namespace {


struct Setting {
  int iterations = 10;       // Bullet's default
  double friction = 0.5;     // Bullet's default per body: 0.25 combined (the product) with the floor's 0.5
  double floorFriction = 0.5;
  double erp2 = 0.2;         // contact error reduction, the default
  bool splitImpulse = true;  // the default
};

Setting settingNamed(const std::string& name) {
  Setting s;
  if (name == "tuned") {
    // Rolling and spinning friction stay off (their defaults): the sphere must
    // roll and pivot freely. Friction high enough never to slide, many more
    // solver iterations.
    s.iterations = 100;
    s.friction = 10.0;
    s.floorFriction = 1.0;
  }
  return s;
}

btVector3 bt(const Vec3& v) { return btVector3(v.x(), v.y(), v.z()); }
Vec3 eig(const btVector3& v) { return Vec3(v.x(), v.y(), v.z()); }

btMatrix3x3 btRotation(const Mat3& m) {
  return btMatrix3x3(m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2));
}

class BulletWorld final : public PeerWorld {
 public:
  BulletWorld(const PeerScene& scene, const Setting& s, double timestep) : h_(timestep), radius_(scene.params.radius) {
    dispatcher_ = std::make_unique<btCollisionDispatcher>(&configuration_);
    world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), &broadphase_, &solver_, &configuration_);
    const physics::HemisphereParams& p = scene.params;
    world_->setGravity(btVector3(0, 0, -p.gravity));
    btContactSolverInfo& info = world_->getSolverInfo();
    info.m_numIterations = s.iterations;
    info.m_erp2 = s.erp2;
    info.m_splitImpulse = s.splitImpulse;

    floor_ = std::make_unique<btRigidBody>(0.0, nullptr, &floorShape_);
    floor_->setFriction(s.floorFriction);
    world_->addRigidBody(floor_.get());

    const Pose start = poseOf(p, scene.x0);
    const Vec3 comArm = start.rotation * shellComOffset(p.radius);
    sphere_.setUnscaledRadius(p.radius);
    shellShape_.addChildShape(btTransform(btMatrix3x3::getIdentity(), btVector3(0, 0, 3.0 * p.radius / 8.0)),
                              &sphere_);
    const Vec3 I = shellPrincipalInertia(p);
    const double rider = riderInertia(p);  // the point's
    btRigidBody::btRigidBodyConstructionInfo shellInfo(p.shellMass, nullptr, &shellShape_,
                                                       btVector3(I.x() - rider, I.y() - rider, I.z() - rider));
    shellInfo.m_friction = s.friction;
    shellInfo.m_rollingFriction = 0.0;
    shellInfo.m_spinningFriction = 0.0;
    shellInfo.m_startWorldTransform = btTransform(btRotation(start.rotation), bt(Vec3(start.faceCentre + comArm)));
    shell_ = std::make_unique<btRigidBody>(shellInfo);
    shell_->setLinearVelocity(bt(Vec3(start.faceCentreVelocity + start.omega.cross(comArm))));
    shell_->setAngularVelocity(bt(start.omega));
    shell_->setActivationState(DISABLE_DEACTIVATION);
    world_->addRigidBody(shell_.get());

    btRigidBody::btRigidBodyConstructionInfo pointInfo(p.pointMass, nullptr, &empty_,
                                                       btVector3(rider, rider, rider));
    pointInfo.m_startWorldTransform = btTransform(btRotation(start.rotation), bt(start.point));
    point_ = std::make_unique<btRigidBody>(pointInfo);
    point_->setLinearVelocity(bt(start.pointVelocity));
    point_->setAngularVelocity(bt(start.omega));
    point_->setActivationState(DISABLE_DEACTIVATION);
    world_->addRigidBody(point_.get(), 0, 0);  // collides with nothing

    // Frame A: the face centre in the shell's centre-of-mass frame; frame B:
    // the point's own frame. Their offset in A's axes is (x_p, y_p, 0).
    faceInShell_ = btTransform(btMatrix3x3::getIdentity(), btVector3(0, 0, 3.0 * p.radius / 8.0));
    slide_ = std::make_unique<btGeneric6DofSpring2Constraint>(*shell_, *point_, faceInShell_, btTransform::getIdentity());
    slide_->setLimit(0, 1, -1);  // lower > upper: free
    slide_->setLimit(1, 1, -1);
    slide_->setLimit(2, 0, 0);
    for (int axis = 3; axis < 6; ++axis) slide_->setLimit(axis, 0, 0);
    world_->addConstraint(slide_.get(), true);
  }
  ~BulletWorld() override {
    world_->removeConstraint(slide_.get());
    world_->removeRigidBody(point_.get());
    world_->removeRigidBody(shell_.get());
    world_->removeRigidBody(floor_.get());
  }

  Pose pose() const override {
    Pose pose;
    const btTransform& t = shell_->getCenterOfMassTransform();
    const btMatrix3x3& b = t.getBasis();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) pose.rotation(r, c) = b[r][c];
    pose.omega = eig(shell_->getAngularVelocity());
    const Vec3 toCentre = pose.rotation * -shellComOffset(radius_);
    pose.faceCentre = eig(t.getOrigin()) + toCentre;
    pose.faceCentreVelocity = eig(shell_->getLinearVelocity()) + pose.omega.cross(toCentre);
    pose.point = eig(point_->getCenterOfMassPosition());
    pose.pointVelocity = eig(point_->getLinearVelocity());
    return pose;
  }
  void setPointForce(const Vec3& f) override { point_->applyCentralForce(bt(f)); }
  void step() override {
    // The 6-dof constraint applies its linear rows at the frames' origins, so
    // frame A is moved to where the point is at the start of each step: the
    // face's normal force then acts on the shell at the point, as it must.
    const btVector3 offset = shell_->getCenterOfMassTransform().invXform(point_->getCenterOfMassPosition());
    faceInShell_.setOrigin(btVector3(offset.x(), offset.y(), faceInShell_.getOrigin().z()));
    slide_->setFrames(faceInShell_, btTransform::getIdentity());
    world_->stepSimulation(h_, 0);  // 0 substeps: exactly one step of h
  }

 private:
  double h_;
  double radius_;
  btDefaultCollisionConfiguration configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  btStaticPlaneShape floorShape_{btVector3(0, 0, 1), 0};
  btSphereShape sphere_{1.0};
  btCompoundShape shellShape_;
  btEmptyShape empty_;
  std::unique_ptr<btRigidBody> floor_, shell_, point_;
  std::unique_ptr<btGeneric6DofSpring2Constraint> slide_;
  btTransform faceInShell_;
};

class BulletEngine final : public PeerEngine {
 public:
  std::string name() const override { return "bullet"; }
  std::string version() const override { return "3.24 (" + std::to_string(btGetVersion()) + "), double precision"; }
  std::vector<PeerSetting> settings() const override {
    return {{"default", "Bullet's defaults: 10 solver iterations, friction 0.5 per body (0.25 combined), ERP2 0.2, "
                        "split impulse"},
            {"tuned", "100 solver iterations, friction 10 (combined with the floor's 1), rolling and spinning "
                      "friction off"}};
  }
  std::unique_ptr<PeerWorld> build(const PeerScene& scene, const std::string& setting, double timestep,
                                   std::string&) const override {
    return std::make_unique<BulletWorld>(scene, settingNamed(setting), timestep);
  }
};

}  // namespace

std::unique_ptr<PeerEngine> makeBulletEngine() { return std::make_unique<BulletEngine>(); }

}  // namespace hemiroll::tools::peers
