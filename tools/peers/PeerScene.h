#pragma once
// The scenes of the peer-engine study (issue 15), the rigid-body picture of
// our state that every engine starts from, and the one measurement all runs
// share. Owns: scene definitions, the 12-state -> bodies conversion, the
// sample (contact point, tilt, slip, energy). Must not know any engine: the
// peers read a Pose back from their own bodies and call sampleOf, so every
// engine, ours included, is measured by the same code.

#include <memory>
#include <string>
#include <vector>

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::tools::peers {

using physics::Mat3;
using physics::Vec2;
using physics::Vec3;

enum class PointDrive {
  Free,        // the point slides freely on the frictionless face
  Tether,      // undamped spring to a fixed proxy (M2): a world force on the point
  Prescribed,  // the point follows p(t) in face coordinates (slide joints driven)
};

struct PeerScene {
  std::string name;
  std::string description;
  physics::HemisphereParams params;
  physics::ForceDrivenState x0 = physics::ForceDrivenState::Zero();  // at t = 0, p and p' included
  PointDrive drive = PointDrive::Free;
  Vec3 proxy = Vec3::Zero();         // Tether: spring anchor [m]
  double tetherStiffness = 0.0;      // Tether: k_r [N/m]
  std::shared_ptr<const physics::MassPointTrajectory> trajectory;  // Prescribed
  double horizon = 0.0;              // [s]
  bool conservative = false;         // energy (plus the spring's) is an invariant
};

// Every scene of the study. quick: horizons cut to 0.2 s (the ctest smoke run).
std::vector<PeerScene> peerScenes(bool quick);

// Where the bodies are, in the base frame: what every engine reads back.
struct Pose {
  Mat3 rotation = Mat3::Identity();   // shell body frame (z = face normal) -> base
  Vec3 faceCentre = Vec3::Zero();     // = the sphere's centre [m]
  Vec3 faceCentreVelocity = Vec3::Zero();
  Vec3 omega = Vec3::Zero();          // shell angular velocity, base frame [rad/s]
  Vec3 point = Vec3::Zero();          // mass point [m]
  Vec3 pointVelocity = Vec3::Zero();  // [m/s]
};

// The shell's centre of mass in its body frame: 3R/8 below the face centre.
inline Vec3 shellComOffset(double radius) { return Vec3(0.0, 0.0, -3.0 * radius / 8.0); }
// Principal inertias about the centre of mass: 83/320 m_s R^2 (x, y), 2/5 m_s R^2 (z).
Vec3 shellPrincipalInertia(const physics::HemisphereParams& p);

// The isotropic inertia [kg m^2] each engine gives a body riding on the
// shell (the point; ODE's carrier, which shares it with the point): an engine
// body needs one, and since a rider cannot turn relative to the shell, the
// same is taken off the shell's, so that the total is exact. A tenth of the
// shell's smallest rather than a token 1e-12: with 1e-12, Bullet's tuned
// runs took 1.8x the CPU time and its tether at 0.5 ms left the face at 2.8 s
// (measured); MuJoCo and ODE gave the same errors either way.
inline double riderInertia(const physics::HemisphereParams& p) { return 0.1 * shellPrincipalInertia(p).x(); }

// The 12-state as bodies: no slip and no penetration by construction.
Pose poseOf(const physics::HemisphereParams& params, const physics::ForceDrivenState& x);

struct Sample {
  double t = 0.0;
  Vec2 contact = Vec2::Zero();  // contact point on the plane = the sphere centre's (x, y) [m]
  double tilt = 0.0;            // angle of the face normal from the vertical [rad]
  double slip = 0.0;            // horizontal speed of the shell's material point at the contact [m/s]
  double penetration = 0.0;     // how far the sphere is below the plane (> 0) [m]
  double energy = 0.0;          // kinetic + gravity (+ the tether's spring) [J]
  Vec2 p = Vec2::Zero();        // mass point in face coordinates [m]
};

Sample sampleOf(const PeerScene& scene, const Pose& pose, double t);

// The time between samples; a divisor-friendly 10 ms so that every engine's
// time step lands on it.
inline constexpr double kSampleInterval = 0.01;

}  // namespace hemiroll::tools::peers
