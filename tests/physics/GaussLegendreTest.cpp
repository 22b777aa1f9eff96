// GaussLegendre.h: symmetric collocation against RK4 on the energy error of
// a conservative motion. The scene is the undamped
// M2 tether to a fixed proxy (H = E + k |r_p - r_h|^2 / 2 exactly conserved;
// physics-notes.md), 60 s at h = 2 ms (twice the paper's step, so that RK4's
// drift shows within a test's time).

#include <gtest/gtest.h>

#include <cstdio>

#include "engine/physics/Physics.h"

namespace hemiroll::test {
namespace {

using namespace physics;

struct TetherRun {
  double firstHalf = 0.0;   // max |H - H0| over [0, 30 s] [J]
  double secondHalf = 0.0;  // max |H - H0| over [30, 60 s] [J]
  double final = 0.0;       // |H(60) - H0|
  double early = 0.0;       // max |H - H0| over [0, 6 s]
};

template <class M>
TetherRun runTether() {
  ForceDrivenSystem sys{HemisphereParams{}};
  ForceDrivenState x;
  x << 0.005, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.05, 0.0, 0.0;
  auto pointAt = [&](const ForceDrivenState& s) {
    using namespace force_slot;
    const ModelConstants& c = sys.dynamics().constants();
    return pointKinematics(geometryOf(c, s), c.params.radius, s[u_a], s[v_a], Vec3(s[w_x], s[w_y], s[w_z])).position;
  };
  const Vec3 proxy = pointAt(x) + Vec3(0.003, -0.004, 0.003);
  const double k = 250.0;
  sys.setCoupling(CouplingDef{ForceMethod::M2, k, 0.0, 1.0, false});
  sys.holdProxy({proxy, Vec3::Zero()});
  auto H = [&](const ForceDrivenState& s) {
    return mechanicalEnergy(sys.dynamics(), s).total() + 0.5 * k * (pointAt(s) - proxy).squaredNorm();
  };
  const double h0 = H(x), h = 2e-3;
  M method;
  TetherRun run;
  for (int i = 0; i < 30000; ++i) {
    method.step(sys, i * h, x, h);
    if ((i + 1) % 50 != 0) continue;  // every 0.1 s
    const double d = std::abs(H(x) - h0);
    (i < 15000 ? run.firstHalf : run.secondHalf) = std::max(i < 15000 ? run.firstHalf : run.secondHalf, d);
    if (i < 3000) run.early = std::max(run.early, d);
    run.final = d;
  }
  std::printf("[measured] tether 60 s, h = 2 ms, %s: max |dH| first 6 s %.2e J, [0,30] %.2e J, [30,60] %.2e J, "
              "final %.2e J\n",
              method.name().data(), run.early, run.firstHalf, run.secondHalf, run.final);
  return run;
}

TEST(GaussLegendre, EnergyErrorGrowsFarSlowerThanRk4s) {
  const TetherRun rk4 = runTether<RungeKutta4<12>>();
  const TetherRun g2 = runTether<GaussLegendre2<12>>();
  const TetherRun g3 = runTether<GaussLegendre3<12>>();
  // RK4: a secular drift, so the error at 60 s is many times the error seen
  // in the first 6 s (linear growth gives ~10x; 4x leaves room for the
  // oscillating part).
  EXPECT_GT(rk4.final, 4.0 * rk4.early);
  // Gauss-Legendre: a FINDING, not the textbook claim. Rolling without
  // slipping is nonholonomic, not Hamiltonian, so symplecticity buys nothing
  // and only symmetry remains; the energy error of this (chaotic) tether is
  // NOT bounded: it grows (measured [30,60] / [0,30] = 2.0 for gauss2, 2.5
  // for gauss3; over 1 h at 1 ms: docs/WORK_PRECISION.md) but hundreds to
  // thousands of times slower than RK4's. What is asserted is that margin:
  // gauss2 has RK4's order (4) and must stay 100x below it, gauss3 1000x.
  EXPECT_LT(g2.secondHalf, 0.01 * rk4.secondHalf);
  EXPECT_LT(g3.secondHalf, 0.001 * rk4.secondHalf);
}

TEST(GaussLegendre, FixedPointIterationConvergesWithoutHittingTheCap) {
  ForceDrivenSystem sys{HemisphereParams{}};
  ForceDrivenState x;
  x << 0.002, -0.001, 0.0, 0.004, 0.2, -0.1, 4.0, 0.0, 0.0, 0.08, -0.05, 0.3;
  GaussLegendre3<12> g;
  for (int i = 0; i < 1000; ++i) g.step(sys, i * 1e-3, x, 1e-3);
  const double perStep = static_cast<double>(g.iterations()) / 1000.0;
  std::printf("[measured] gauss3 at 1 ms, free motion: %.1f sweeps per step, %lld capped\n", perStep, g.cappedSteps());
  EXPECT_EQ(g.cappedSteps(), 0);
  // The extrapolated start makes round-off convergence cheap: well under the cap.
  EXPECT_LT(perStep, 20.0);
}

}  // namespace
}  // namespace hemiroll::test
