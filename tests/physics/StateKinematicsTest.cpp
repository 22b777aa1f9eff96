// engine/physics/StateKinematics: the mass point's place from a 12-state,
// against the rotation written out as eq. (6)'s three elementary turns
// (AngleAxis, not makeOrientation) and against exact invariants.

#include "engine/physics/StateKinematics.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace hemiroll::physics {
namespace {

namespace slot = force_slot;

ForceDrivenState tiltedState() {
  ForceDrivenState x = ForceDrivenState::Zero();
  x[slot::x_p] = 0.012;
  x[slot::y_p] = -0.007;
  x[slot::u_a] = 0.03;
  x[slot::v_a] = -0.02;
  x[slot::u_o] = 0.3;
  x[slot::v_o] = -0.2;
  x[slot::psi] = 1.1;
  return x;
}

TEST(StateKinematicsTest, MassPointMatchesEquationSixWrittenOut) {
  const double radius = 0.05;
  const ForceDrivenState x = tiltedState();
  // R = Rz(psi)^T Rx(v_o)^T Ry(u_o)^T: each transpose is the turn by minus the angle.
  const Mat3 R = (Eigen::AngleAxisd(-x[slot::psi], Vec3::UnitZ()) * Eigen::AngleAxisd(-x[slot::v_o], Vec3::UnitX()) *
                  Eigen::AngleAxisd(-x[slot::u_o], Vec3::UnitY()))
                     .toRotationMatrix();
  const Vec3 expected = Vec3(x[slot::u_a], x[slot::v_a], radius) + R * Vec3(x[slot::x_p], x[slot::y_p], 0.0);
  const Vec3 p = massPointPosition(x, radius);
  // A dozen roundings of numbers below 0.1 m: 1e-15 m is a few ulps.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p[i], expected[i], 1e-15) << i;
}

TEST(StateKinematicsTest, MassPointStaysOnTheFaceAtItsDistanceFromTheCentre) {
  const double radius = 0.05;
  const ForceDrivenState x = tiltedState();
  const Vec3 centre(x[slot::u_a], x[slot::v_a], radius);
  const Vec3 offset = massPointPosition(x, radius) - centre;
  EXPECT_NEAR(offset.norm(), std::hypot(x[slot::x_p], x[slot::y_p]), 1e-15);
  // Upright, a turn by psi only: the mass point sits at the centre's height.
  ForceDrivenState upright = x;
  upright[slot::u_o] = upright[slot::v_o] = 0.0;
  EXPECT_NEAR(massPointPosition(upright, radius).z(), radius, 1e-15);
}

TEST(StateKinematicsTest, StateOfAnArrayKeepsEverySlot) {
  std::array<double, 12> a{};
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = 0.5 * static_cast<double>(i) - 1.0;
  const ForceDrivenState x = forceStateOf(a);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(x[i], a[static_cast<std::size_t>(i)]) << kStateNames[i];
}

}  // namespace
}  // namespace hemiroll::physics
