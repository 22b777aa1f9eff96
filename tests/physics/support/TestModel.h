#pragma once
// Shared vocabulary of the physics tests: parameters, random states and the
// elementary rotations written out independently of engine/physics.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <random>

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::test {

using physics::HemisphereParams;
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using State12 = Eigen::Matrix<double, 12, 1>;
using State8 = Eigen::Matrix<double, 8, 1>;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180.0;
inline constexpr double kEps = 2.220446049250313e-16;  // DBL_EPSILON

// The paper's values (Sec. 4): m_p = 1 kg, m_s = 0.1 kg, R = 0.04 m, g = 9.81.
inline HemisphereParams paperParams() { return HemisphereParams{}; }

// hat(a) b = a x b.
Mat3 hat(const Vec3& a);

// R = Rz(psi)^T Rx(v_o)^T Ry(u_o)^T (eq. 6) from Eigen's elementary
// rotations, so that tests do not lean on the engine's expanded matrix.
Mat3 orientationFromAngles(double u_o, double v_o, double psi);

// Ranges of the random 12-state vectors used by the agreement tests.
struct RandomStateSpec {
  double maxTilt = 80.0 * kDeg;  // angle of the face normal from vertical
  double maxPointRadius = 0.95;  // |p| / R
  double maxPointSpeed = 0.3;    // |p'| [m/s] per component
  double maxSpin = 8.0;          // |w_i| [rad/s] per component
  double maxPlane = 0.1;         // |u_a|, |v_a| [m]
};

State12 randomState(std::mt19937_64& rng, const HemisphereParams& params, const RandomStateSpec& spec = {});

// Uniform number in [lo, hi] (std::uniform_real_distribution would do, but
// its output is not specified across standard libraries).
double uniform(std::mt19937_64& rng, double lo, double hi);

}  // namespace hemiroll::test
