// The quaternion formulation of the force-driven model (RotationDrivenSystem)
// against the contact-angle formulation (ForceDrivenSystem), which the other
// suites check against the paper and an independent Newton-Euler model: the
// same physics must come out of both, at every state and along trajectories.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/physics/DormandPrince853.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/RotationDrivenSystem.h"
#include "tests/physics/support/Drives.h"
#include "tests/physics/support/Integration.h"

namespace hemiroll::test {
namespace {

using physics::BodyFrame;
using physics::CouplingDef;
using physics::ForceDrivenState;
using physics::ForceDrivenSystem;
using physics::ForceMethod;
using physics::ProxyPose;
using physics::Quaternion;
using physics::RotationDrivenSystem;
using physics::RotationState;
namespace fs = physics::force_slot;
namespace rs = physics::rotation_slot;

Mat3 matrixOf(const BodyFrame& f) {
  Mat3 R;
  R << f.i.x, f.j.x, f.k.x, f.i.y, f.j.y, f.k.y, f.i.z, f.j.z, f.k.z;
  return R;
}

TEST(BodyRotation, QuaternionGivesTheMatrixOfEq6) {
  std::mt19937_64 rng(41);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double u = uniform(rng, -85 * kDeg, 85 * kDeg), v = uniform(rng, -85 * kDeg, 85 * kDeg);
    const double psi = uniform(rng, -20.0, 20.0);
    const Quaternion q = physics::quaternionFromContactAngles(u, v, psi);
    worst = std::max(worst, (matrixOf(physics::makeBodyFrame(q)) - orientationFromAngles(u, v, psi)).cwiseAbs().maxCoeff());
  }
  // Entries of a rotation are <= 1; the two routes (Eigen's elementary
  // rotations, and matrix -> quaternion -> matrix) each round a few times,
  // with psi up to 20 rad adding its range reduction: 20 eps is ample.
  EXPECT_LT(worst, 20 * kEps);
}

TEST(BodyRotation, NormOfTheQuaternionCarriesNoPhysics) {
  const Quaternion q = physics::quaternionFromContactAngles(0.3, -0.7, 2.1);
  const Quaternion scaled{3.7 * q.w, 3.7 * q.x, 3.7 * q.y, 3.7 * q.z};
  const double difference =
      (matrixOf(physics::makeBodyFrame(q)) - matrixOf(physics::makeBodyFrame(scaled))).cwiseAbs().maxCoeff();
  EXPECT_LT(difference, 8 * kEps);  // only the rounding of 2 / |q|^2 differs
}

TEST(BodyRotation, ContactAnglesRoundTripOnTheContinuousBranch) {
  std::mt19937_64 rng(42);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double u = uniform(rng, -85 * kDeg, 85 * kDeg), v = uniform(rng, -85 * kDeg, 85 * kDeg);
    const double psi = uniform(rng, -20.0, 20.0);
    // The previous psi of a run is within a step of the new one, never pi away.
    const auto a = physics::contactAnglesFromQuaternion(physics::quaternionFromContactAngles(u, v, psi), psi + 0.5);
    worst = std::max({worst, std::abs(a.u_o - u), std::abs(a.v_o - v), std::abs(a.psi - psi)});
  }
  // atan2 of entries good to ~10 eps; at 85 deg of tilt the conditioning of
  // the angles is 1 / cos(85 deg) ~ 11, and psi = 20 carries 20 eps of its own.
  EXPECT_LT(worst, 2e-13);
}

// The inputs both systems take, set on both.
template <class System>
void configure(System& system, int mode, const ProxyPose& proxy) {
  if (mode == 0) system.setFree();
  if (mode == 1) system.setFaceForce(Vec2(0.7, -1.3));
  if (mode >= 2) {
    CouplingDef def;
    def.method = mode == 2 ? ForceMethod::M1 : mode == 3 ? ForceMethod::M2 : ForceMethod::M3;
    system.setCoupling(def);
    system.holdProxy(proxy);
  }
}

TEST(RotationDrivenSystem, DerivativeAgreesWithTheContactAngleModel) {
  const HemisphereParams par = paperParams();
  ForceDrivenSystem angles(par);
  RotationDrivenSystem rotation(par);
  std::mt19937_64 rng(43);
  for (int mode = 0; mode < 5; ++mode) {
    double worstBody = 0.0, worstAngles = 0.0;
    for (int i = 0; i < 500; ++i) {
      const State12 x = randomState(rng, par);
      const ProxyPose proxy{Vec3(uniform(rng, -0.05, 0.05), uniform(rng, -0.05, 0.05), uniform(rng, 0.0, 0.08)),
                            Vec3(uniform(rng, -0.2, 0.2), uniform(rng, -0.2, 0.2), uniform(rng, -0.2, 0.2))};
      configure(angles, mode, proxy);
      configure(rotation, mode, proxy);
      ForceDrivenState da;
      angles.derivative(0.0, x, da);
      const RotationState xr = physics::toRotationState(x);
      RotationState dr;
      rotation.derivative(0.0, xr, dr);

      // p'', w', u_a', v_a' are the same quantities in both.
      const double scale = std::max(1.0, da.head<9>().cwiseAbs().maxCoeff());
      worstBody = std::max(worstBody, (dr.head<9>() - da.head<9>()).cwiseAbs().maxCoeff() / scale);

      // The angle rates follow from q' by the chain rule: differentiate the
      // angles of q + e q' centrally. Step 1e-6: truncation ~1e-12, rounding
      // ~eps / 1e-6 ~ 2e-10, both times the rates' scale.
      const double e = 1e-6;
      RotationState ahead = xr + e * dr, behind = xr - e * dr;
      const ForceDrivenState ca = physics::toContactState(ahead, x[fs::psi]);
      const ForceDrivenState cb = physics::toContactState(behind, x[fs::psi]);
      const Vec3 rates = (ca.tail<3>() - cb.tail<3>()) / (2 * e);
      const double rateScale = std::max(1.0, da.tail<3>().cwiseAbs().maxCoeff());
      worstAngles = std::max(worstAngles, (rates - da.tail<3>()).cwiseAbs().maxCoeff() / rateScale);
    }
    // Two round-off implementations of one formula in frames turned by psi:
    // the 3x3 solve amplifies rounding by the condition of S (~1e2 on these
    // states), so 1e-12 of the largest rate.
    EXPECT_LT(worstBody, 1e-12) << "input mode " << mode;
    EXPECT_LT(worstAngles, 2e-8) << "input mode " << mode;
  }
}

TEST(RotationDrivenSystem, TrajectoriesAgreeWithTheContactAngleModel) {
  const HemisphereParams par = paperParams();
  const CirclingProxy proxy;
  for (int mode = 0; mode < 2; ++mode) {
    ForceDrivenSystem angles(par);
    RotationDrivenSystem rotation(par);
    if (mode == 1) {
      angles.setCoupling(CouplingDef{}, proxy);
      rotation.setCoupling(CouplingDef{}, proxy);
    }
    // The start of ForceDrivenSystemTest's trajectories: p off-centre and
    // moving, tilted ~10 deg, spinning; every term active, well inside the
    // rim for the whole second. (Random starts are no good here: many are
    // top-heavy motions that amplify a 1e-13 difference a thousandfold.)
    State12 x0;
    x0 << 0.004, -0.003, 0.01, 0.005, 0.3, -0.2, 2.0, 0.01, -0.02, 0.12, -0.1, 0.7;
    // DOP853 at tol 1e-13 over 1 s: each model lands within ~1e-12 of the
    // exact solution (AdaptiveIntegratorTest measures the tolerance
    // proportionality), so the two must agree to 1e-9, the bound issue 2
    // sets for independent formulations. (Plain RK4 at 1e-4 s would not do:
    // its two truncation errors differ by ~1e-8 on these states.)
    physics::DormandPrince853<12> reference12;
    physics::DormandPrince853<13> reference13;
    reference12.setTolerance(1e-13);
    reference13.setTolerance(1e-13);
    double ta = 0.0, tr = 0.0;
    ForceDrivenState xa = x0;
    RotationState xr = physics::toRotationState(x0);
    // Free, the mass point slides off the face within ~0.8 s, and from 0.5 s
    // on the motion amplifies a 1e-13 change of x_p a thousandfold and more
    // (measured), beyond what any two double-precision runs can agree on.
    const double horizon = mode == 1 ? 1.0 : 0.5;
    ASSERT_TRUE(reference12.advanceTo(angles, ta, xa, horizon));
    ASSERT_TRUE(reference13.advanceTo(rotation, tr, xr, horizon));
    const ForceDrivenState back = physics::toContactState(xr, xa[fs::psi]);
    const double gap = (back - xa).cwiseAbs().maxCoeff();
    std::printf("[measured] quaternion vs contact angles, %.1f s %s: max |dx| = %.2e\n", horizon,
                mode ? "M3" : "free", gap);
    EXPECT_LT(gap, 1e-9) << "mode " << mode;
  }
}

TEST(RotationDrivenSystem, MarginsMatchTheContactAngleModel) {
  const HemisphereParams par = paperParams();
  ForceDrivenSystem angles(par);
  RotationDrivenSystem rotation(par);
  std::mt19937_64 rng(45);
  RandomStateSpec spec;
  spec.maxTilt = 89.9 * kDeg;
  for (int i = 0; i < 1000; ++i) {
    const State12 x = randomState(rng, par, spec);
    const auto a = angles.margins(0.0, x);
    const auto r = rotation.margins(0.0, physics::toRotationState(x));
    EXPECT_NEAR(a.tilt, r.tilt, 1e-15);  // cos(tilt) in [0, 1], a few roundings apart
    EXPECT_EQ(a.face, r.face);
  }
}

}  // namespace
}  // namespace hemiroll::test
