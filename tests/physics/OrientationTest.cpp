// Orientation.h: eq. (6) against Eigen's elementary rotations, the contact
// kinematics (11)-(15) against finite differences of the orientation matrix,
// and the inverse map.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "engine/physics/Orientation.h"
#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {
namespace {

using physics::contactAnglesFromMatrix;
using physics::contactRates;
using physics::makeOrientation;

TEST(Orientation, MatrixIsEquation6) {
  std::mt19937_64 rng(6);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double u = uniform(rng, -1.5, 1.5), v = uniform(rng, -1.5, 1.5), psi = uniform(rng, -20.0, 20.0);
    const physics::Orientation o = makeOrientation(u, v, psi);
    worst = std::max({worst, (o.R - orientationFromAngles(u, v, psi)).cwiseAbs().maxCoeff(),
                      (o.R * o.R.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff(),
                      std::abs(o.cosTilt() - o.R(2, 2))});
  }
  std::printf("[measured] makeOrientation vs Rz^T Rx^T Ry^T: %.2e\n", worst);
  // Unit-size entries from a few products of sines: a few eps.
  EXPECT_LT(worst, 1e-14);
}

// Moving the angles along the rates of eqs. (13)-(15) must rotate the body
// with angular velocity w: (dR/dt) R^T = hat(w), by central differences.
TEST(Orientation, ContactRatesRotateTheBodyWithOmega) {
  std::mt19937_64 rng(15);
  const double radius = 0.04;
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double u = uniform(rng, -1.4, 1.4), v = uniform(rng, -1.4, 1.4), psi = uniform(rng, -kPi, kPi);
    const Vec3 w(uniform(rng, -10, 10), uniform(rng, -10, 10), uniform(rng, -10, 10));
    const physics::Orientation o = makeOrientation(u, v, psi);
    const physics::ContactRates r = contactRates(o, radius, w);
    const double dt = 1e-6;
    const Mat3 plus = orientationFromAngles(u + r.u_o * dt, v + r.v_o * dt, psi + r.psi * dt);
    const Mat3 minus = orientationFromAngles(u - r.u_o * dt, v - r.v_o * dt, psi - r.psi * dt);
    const Mat3 spin = (plus - minus) / (2 * dt) * o.R.transpose();
    // Central differences: truncation (dt^2 / 6) |R'''| ~ dt^2 s^3 with s the
    // largest angle rate, round-off ~ eps / dt; relative to |w|.
    const double s = std::max({std::abs(r.u_o), std::abs(r.v_o), std::abs(r.psi), 1.0});
    const double tol = 10.0 * (dt * dt * s * s * s + kEps / dt);
    const double err = (spin - hat(w)).cwiseAbs().maxCoeff() / tol;
    worst = std::max(worst, err);
    // No slip, eqs. (11)-(12): the sphere centre moves as w x (R e_z).
    const Vec3 centre = w.cross(Vec3(0, 0, radius));
    worst = std::max(worst, (std::abs(r.u_a - centre.x()) + std::abs(r.v_a - centre.y())) / (radius * kEps * 10));
  }
  std::printf("[measured] (dR/dt) R^T - hat(w): worst error / FD tolerance = %.2f\n", worst);
  EXPECT_LT(worst, 1.0);
}

TEST(Orientation, ContactAnglesInvertTheMatrix) {
  std::mt19937_64 rng(66);
  double worst = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const double u = uniform(rng, -89, 89) * kDeg, v = uniform(rng, -89, 89) * kDeg, psi = uniform(rng, -30.0, 30.0);
    const physics::ContactAngles a = contactAnglesFromMatrix(makeOrientation(u, v, psi).R, psi + uniform(rng, -3, 3));
    worst = std::max({worst, std::abs(a.u_o - u), std::abs(a.v_o - v), std::abs(a.psi - psi)});
  }
  std::printf("[measured] contactAnglesFromMatrix round trip: %.2e rad\n", worst);
  // atan2 of entries accurate to ~eps, psi amplified by 1/cos v <= 57 at 89 deg,
  // plus eps * |psi| ~ 7e-15 from the 2 pi shifts on |psi| <= 30.
  EXPECT_LT(worst, 1e-12);
}

}  // namespace
}  // namespace hemiroll::test
