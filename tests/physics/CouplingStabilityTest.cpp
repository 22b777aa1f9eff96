// CouplingStability.h and SubsteppingIntegrator.h: RK4's stability region,
// the paper's stiffest coupling at h = 1 ms, couplings that diverge at 1 ms
// and run stably under the policy, bit-identity where the policy is not
// needed, and the measured divergence thresholds and spin limit of
// docs/PHYSICS.md, "Where explicit methods become unstable".

#include "engine/physics/CouplingStability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "engine/physics/Energy.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/Stepper.h"
#include "engine/physics/SubsteppingIntegrator.h"
#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {
namespace {

using physics::CouplingDef;
using physics::DomainEvent;
using physics::ForceMethod;

TEST(CouplingStability, Rk4RegionOnTheAxes) {
  // Classical values: the real-axis limit is the root of R(z) = -1 near
  // -2.785 (2.7852935...), the imaginary one 2 sqrt 2 (|R(iy)|^2 = 1 - y^6/72
  // + y^8/576). The bisection is run to round-off; 1e-6 allows the stride.
  EXPECT_NEAR(physics::rk4StabilityRadius(kPi), 2.7852935, 1e-6);
  EXPECT_NEAR(physics::rk4StabilityRadius(0.5 * kPi), 2.0 * std::sqrt(2.0), 1e-6);
}

TEST(CouplingStability, ModesOfTheScalarOscillator) {
  // Paper gains, M3 alpha = 4: k = 1000 N/m, c = 40 N s/m, m_p = 1 kg:
  // lambda = -20 +- i sqrt(1000 - 400).
  const physics::CouplingModes m = physics::couplingModes(CouplingDef{ForceMethod::M3, 250.0, 10.0, 4.0, false}, 1.0);
  EXPECT_DOUBLE_EQ(m.lambdaRe, -20.0);
  EXPECT_DOUBLE_EQ(m.lambdaIm, std::sqrt(600.0));
  // Overdamped: the fast root -(c + sqrt(c^2 - 4 k m)) / 2m; M1 ignores alpha.
  const physics::CouplingModes o = physics::couplingModes(CouplingDef{ForceMethod::M1, 100.0, 10.0, 4.0, false}, 0.01);
  EXPECT_DOUBLE_EQ(o.lambdaRe, -(10.0 + std::sqrt(100.0 - 4.0)) / 0.02);
  EXPECT_EQ(o.lambdaIm, 0.0);
}

// A coupled run from just off the held proxy: upright, the mass point 2 mm
// from the face centre with the proxy at the centre (M3 also pulls it 1 mm
// along the normal). Stable couplings settle; unstable ones blow up and end
// in an event (off the face, tip-over or non-finite) within the horizon.
struct CoupledRun {
  DomainEvent event;
  physics::ForceDrivenState state;
  double energyBalanceError;  // |E + spring energy| at the end minus at the start, undamped only
};

CoupledRun runCoupled(const HemisphereParams& par, const CouplingDef& def, double h, int substeps, double duration) {
  physics::ForceDrivenSystem sys(par);
  sys.setCoupling(def);
  sys.holdProxy({Vec3(0.0, 0.0, par.radius + 0.001), Vec3::Zero()});
  physics::RungeKutta4<12> rk4;
  physics::SubsteppingIntegrator<12> integrator(rk4, substeps);
  State12 x = State12::Zero();
  x[0] = 0.002;
  physics::Stepper<12> stepper(sys, integrator, x);
  const long long steps = std::llround(duration / h);
  for (long long i = 0; i < steps && !stepper.halted(); ++i) stepper.advance(h);
  return {stepper.event(), stepper.state(), 0.0};
}

bool diverges(const HemisphereParams& par, const CouplingDef& def, double h, int substeps = 1) {
  return runCoupled(par, def, h, substeps, 2.0).event != DomainEvent::None;
}

TEST(CouplingStability, PaperStiffestCouplingIsStableAtOneMillisecond) {
  // The paper's stiffest settings (k_r = 250 N/m, k_v = 10 N s/m, M3 alpha up
  // to 4, m_p = 1 kg) need no substeps: |lambda| ~ 32 /s, h |lambda| = 0.03.
  for (double alpha : {1.0, 2.0, 4.0}) {
    for (ForceMethod method : {ForceMethod::M1, ForceMethod::M2, ForceMethod::M3}) {
      const CouplingDef def{method, 250.0, 10.0, alpha, false};
      EXPECT_EQ(physics::couplingStepPolicy("rk4", def, 1.0, 1e-3).substeps, 1);
      const CoupledRun run = runCoupled(paperParams(), def, 1e-3, 1, 10.0);
      const CoupledRun fine = runCoupled(paperParams(), def, 1e-3, 4, 10.0);
      EXPECT_EQ(run.event, DomainEvent::None) << "alpha " << alpha;
      ASSERT_EQ(fine.event, DomainEvent::None) << "alpha " << alpha;
      // Stable and accurate: after 10 s the 1 ms run agrees with one at
      // 0.25 ms to 1 micrometre, 5e-4 of the 2 mm start offset (measured
      // ~1e-7 m: RK4's truncation on the coupling at h |lambda| = 0.03 and on
      // the rocking, accumulated over 10 s of lightly damped motion). An
      // unstable run grows without bound and leaves the face within 2 s.
      const double gap = std::hypot(run.state[0] - fine.state[0], run.state[1] - fine.state[1]);
      std::printf("[measured] paper gains, %s alpha %.0f: |p(1 ms) - p(0.25 ms)| at 10 s = %.2e m\n",
                  physics::forceMethodName(method), alpha, gap);
      EXPECT_LT(gap, 1e-6) << "alpha " << alpha;
    }
  }
}

TEST(CouplingStability, PolicySubstepsACouplingThatDivergesAtOneMillisecond) {
  // m_p = 2 g with the stress suite's stiffest in-face gains (M2, k_r = 5000
  // N/m, k_v = 10 N s/m): k_v/m_p = 5000 /s, overdamped, the fast root near
  // -4900 /s, h |lambda| = 4.9 at 1 ms, beyond RK4's 2.785 on the real axis.
  HemisphereParams par = paperParams();
  par.pointMass = 0.002;
  const CouplingDef def{ForceMethod::M2, 5000.0, 10.0, 1.0, false};
  ASSERT_TRUE(diverges(par, def, 1e-3, 1)) << "this coupling must diverge unassisted, or the test shows nothing";
  const physics::StepPolicy policy = physics::couplingStepPolicy("rk4", def, par.pointMass, 1e-3);
  std::printf("[measured] m_p = 2 g, M2, k_r = 5000, k_v = 10: hMax = %.3g s, %d substeps\n",
              policy.maxStableStep, policy.substeps);
  EXPECT_GT(policy.substeps, 1);
  const CoupledRun run = runCoupled(par, def, 1e-3, policy.substeps, 2.0);
  EXPECT_EQ(run.event, DomainEvent::None);
  EXPECT_TRUE(run.state.allFinite());
}

TEST(CouplingStability, PolicyChangesNothingWhereNotNeeded) {
  // One substep must be the wrapped method itself: bit-identical states.
  const CouplingDef def{ForceMethod::M3, 250.0, 10.0, 2.0, false};
  const CoupledRun plain = [&] {
    physics::ForceDrivenSystem sys(paperParams());
    sys.setCoupling(def);
    sys.holdProxy({Vec3(0.0, 0.0, 0.041), Vec3::Zero()});
    physics::RungeKutta4<12> rk4;
    State12 x = State12::Zero();
    x[0] = 0.002;
    physics::Stepper<12> stepper(sys, rk4, x);
    for (int i = 0; i < 3000; ++i) stepper.advance(1e-3);
    return CoupledRun{stepper.event(), stepper.state(), 0.0};
  }();
  const int substeps = physics::couplingStepPolicy("rk4", def, 1.0, 1e-3).substeps;
  ASSERT_EQ(substeps, 1);
  const CoupledRun policed = runCoupled(paperParams(), def, 1e-3, substeps, 3.0);
  EXPECT_EQ(std::memcmp(plain.state.data(), policed.state.data(), sizeof(double) * 12), 0);
}

// The measured thresholds of docs/PHYSICS.md. For each mass point and
// damping, bisect on k_r for the smallest stiffness at which RK4 at 1 ms
// diverges (M2, isotropic), and compare with the estimate's limit (the
// policy's hMax without the safety factor equals 1 ms there).
// The search runs over k_r / m_p from 1e3 (well stable numerically, h omega
// = 0.03, and stiff enough to hold the point against gravity: softer springs
// let it slide off the face, which is physics, not divergence) to 1e8.
double measuredDivergenceStiffness(double pointMass, double damping) {
  HemisphereParams par = paperParams();
  par.pointMass = pointMass;
  double lo = 1e3 * pointMass, hi = 1e8 * pointMass;  // [N/m]; stable at lo, unstable at hi
  if (diverges(par, CouplingDef{ForceMethod::M2, lo, damping, 1.0, false}, 1e-3)) return 0.0;
  if (!diverges(par, CouplingDef{ForceMethod::M2, hi, damping, 1.0, false}, 1e-3)) return INFINITY;
  for (int i = 0; i < 30 && hi / lo > 1.01; ++i) {
    const double mid = std::sqrt(lo * hi);
    (diverges(par, CouplingDef{ForceMethod::M2, mid, damping, 1.0, false}, 1e-3) ? hi : lo) = mid;
  }
  return hi;
}

double predictedDivergenceStiffness(double pointMass, double damping) {
  double lo = 1e3 * pointMass, hi = 1e8 * pointMass;
  auto unstable = [&](double k) {
    const physics::StepPolicy p =
        physics::couplingStepPolicy("rk4", CouplingDef{ForceMethod::M2, k, damping, 1.0, false}, pointMass, 1e-3);
    return p.maxStableStep / physics::StepPolicy::kSafety < 1e-3;
  };
  if (unstable(lo)) return 0.0;
  if (!unstable(hi)) return INFINITY;
  for (int i = 0; i < 60 && hi / lo > 1.0001; ++i) {
    const double mid = std::sqrt(lo * hi);
    (unstable(mid) ? hi : lo) = mid;
  }
  return hi;
}

TEST(CouplingStabilityScan, MeasuredThresholdsMatchTheEstimate) {
  std::printf("[measured] RK4 at h = 1 ms, M2: smallest k_r [N/m] that diverges\n");
  std::printf("  m_p [kg]  k_v [N s/m]  measured   predicted  ratio  sqrt(k/m_p) h  k_v/m_p h\n");
  for (double m : {0.001, 0.01, 0.1, 1.0, 10.0, 100.0}) {
    for (double c : {0.0, 1.0, 10.0, 100.0}) {
      const double measured = measuredDivergenceStiffness(m, c), predicted = predictedDivergenceStiffness(m, c);
      std::printf("  %7.3g  %11.3g  %9.4g  %9.4g  %5.3f  %13.3f  %9.3f\n", m, c, measured, predicted,
                  predicted > 0.0 ? measured / predicted : 1.0, std::sqrt(measured / m) * 1e-3, c / m * 1e-3);
      if (predicted == 0.0) {
        // Damping alone beyond the real-axis limit (k_v/m_p h > 2.785): every
        // stiffness diverges, and so must the real run.
        EXPECT_EQ(measured, 0.0) << "m_p " << m << " k_v " << c;
        continue;
      }
      // The estimate takes the coupling's mode alone, with the smallest mass
      // it can move (m_p). With the paper's hemisphere (0.1 kg) it matches
      // the measured threshold to 0.5% up to m_p = 1 kg; with a heavy point
      // on that light hemisphere (m_p = 10 kg) the hemisphere's own fast
      // rocking adds to the coupling and RK4 diverges earlier, at ~0.7 of
      // the predicted stiffness (0.83 of the frequency). The policy's safety
      // factor 0.5 on h covers a ratio down to 0.5^2 = 0.25 in k (stiffness
      // goes with the square of the frequency); the test asks for 0.3.
      // At m_p/m_s = 1000 (m_p = 100 kg) the estimate no longer holds: RK4
      // diverges at h sqrt(k/m_p) = 0.8 whatever the damping (printed, not
      // asserted; docs/PHYSICS.md): there the body's modes, not the
      // coupling's, set the limit, and the adaptive methods are the answer.
      if (m / paperParams().shellMass > 100.0) continue;
      EXPECT_GT(measured / predicted, 0.3) << "m_p " << m << " k_v " << c;
    }
  }
}

// Spin. Free motion, mass point at the face centre, tilt 0.05 rad,
// spin S about the face normal, 1 s at h = 1 ms. Spin enters as an
// imaginary eigenvalue of about S, so RK4 should lose accuracy as (h S)^4
// and blow up near h S = 2 sqrt 2 (its imaginary-axis limit).
double spinEnergyError(double spin) {
  physics::ForceDrivenSystem sys(paperParams());
  State12 x = State12::Zero();
  x[10] = 0.05;
  x[6] = spin;
  physics::RungeKutta4<12> rk4;
  physics::Stepper<12> stepper(sys, rk4, x);
  const double e0 = physics::mechanicalEnergy(sys.dynamics(), x).total();
  for (int i = 0; i < 1000 && !stepper.halted(); ++i) stepper.advance(1e-3);
  return std::abs(physics::mechanicalEnergy(sys.dynamics(), stepper.state()).total() - e0) / std::abs(e0);
}

TEST(CouplingStabilityScan, SpinLimitOfRk4AtOneMillisecond) {
  std::printf("[measured] RK4 at 1 ms, free spin: relative energy error after 1 s (or at the event)\n");
  double errors[6];
  const double spins[6] = {100.0, 300.0, 1000.0, 2000.0, 3000.0, 3500.0};
  for (int i = 0; i < 6; ++i) {
    errors[i] = spinEnergyError(spins[i]);
    std::printf("  spin %6.0f rad/s  h spin %.1f  %.2e\n", spins[i], spins[i] * 1e-3, errors[i]);
  }
  // The stress suite's 100 rad/s is well resolved ((h S)^4 = 1e-4, and the
  // motion is mostly steady spin: measured 4e-8); from h S = 2 on the run
  // blows up (energy error of order one or more).
  EXPECT_LT(errors[0], 1e-6);
  EXPECT_GT(errors[3], 0.5);
  EXPECT_GT(errors[5], 1.0);
}

}  // namespace
}  // namespace hemiroll::test
