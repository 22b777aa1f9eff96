// The engine's reduced dynamics (RollingDynamics: 3x3 Schur form) against the
// paper's equations transcribed literally (tests/physics/support/PaperEquations.h):
// the 5x5 system (23)-(29), the Schur blocks (33)-(40) with (37) corrected,
// and the inertia J_c of eq. (21).

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cstdio>

#include "engine/physics/ForceDrivenSystem.h"
#include "tests/physics/support/PaperEquations.h"

namespace hemiroll::test {
namespace {

constexpr int kSamples = 1000;

// Relative error of matrices: the entries are O(m_s R^2) or O(1/m_p), and a
// 5x5 or 3x3 inverse of a system with condition number ~1e3 is accurate to
// ~cond * eps ~ 2e-13 relative; 1e-11 leaves margin for the worst state.
constexpr double kRoundOff = 1e-11;

template <class M>
double relativeDifference(const M& a, const M& b) {
  return (a - b).norm() / std::max(a.norm(), b.norm());
}

TEST(RollingDynamics, ContactInertiaMatchesEquation21) {
  const HemisphereParams par = paperParams();
  physics::RollingDynamics dyn(par);
  std::mt19937_64 rng(21);
  double worst = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const State12 x = randomState(rng, par);
    const PaperTerms t = paperTerms(par, x);
    worst = std::max(worst, relativeDifference(dyn.contactInertia(t.k), t.Jc));
  }
  std::printf("[measured] J_c: max relative difference %.2e\n", worst);
  // Closed forms of a few products: error of a handful of roundings.
  EXPECT_LT(worst, 1e-14);
}

// Engine [p''; w'] against the 5x5 solve of (30), worst relative error.
double compareWithFiveByFive(const physics::ForceDrivenSystem& engine, const HemisphereParams& par,
                             const Vec2& faceForce, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  double worst = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const State12 x = randomState(rng, par);
    physics::ForceDrivenState d;
    engine.derivative(0.0, x, d);
    const PaperTerms t = paperTerms(par, x);
    const Vec5 paper = solveFiveByFive(t, t.RN * faceForce);
    Vec5 mine;
    mine << d.segment<2>(2), d.segment<3>(4);
    // Scale by the sizes that cancel: g/R for w', g for p''.
    const double w2 = x.segment<3>(4).squaredNorm();
    const double omegaScale = std::max(par.gravity / par.radius, w2);
    const double pointScale = std::max(par.gravity, w2 * par.radius);
    worst = std::max({worst, (mine.head<2>() - paper.head<2>()).norm() / pointScale,
                      (mine.tail<3>() - paper.tail<3>()).norm() / omegaScale});
  }
  return worst;
}

TEST(RollingDynamics, AgreesWithLiteralFiveByFiveSolve) {
  const HemisphereParams par = paperParams();
  physics::ForceDrivenSystem engine(par);
  const double free = compareWithFiveByFive(engine, par, Vec2::Zero(), 31);
  const Vec2 f(2.0, -0.7);
  engine.setFaceForce(f);
  const double forced = compareWithFiveByFive(engine, par, f, 32);
  std::printf("[measured] 5x5 vs engine: free %.2e, face force %.2e (relative)\n", free, forced);
  EXPECT_LT(free, kRoundOff);
  EXPECT_LT(forced, kRoundOff);
}

TEST(RollingDynamics, GeneralSchurBlocksInvertTheFiveByFive) {
  // (33)-(36) are the textbook block inverse; a check of the transcription.
  const HemisphereParams par = paperParams();
  std::mt19937_64 rng(33);
  double worst = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const PaperTerms t = paperTerms(par, randomState(rng, par));
    const InverseBlocks direct = blocksOfInverse(t.H.inverse());
    const InverseBlocks schur = schurBlocksGeneral(t);
    worst = std::max({worst, relativeDifference(direct.ss, schur.ss), relativeDifference(direct.ps, schur.ps),
                      relativeDifference(direct.sp, schur.sp), relativeDifference(direct.pp, schur.pp)});
  }
  std::printf("[measured] (33)-(36) vs inverse: %.2e\n", worst);
  EXPECT_LT(worst, kRoundOff);
}

TEST(RollingDynamics, CorrectedEquation37AndEquations38To40Hold) {
  const HemisphereParams par = paperParams();
  std::mt19937_64 rng(37);
  double worst = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const PaperTerms t = paperTerms(par, randomState(rng, par));
    const InverseBlocks direct = blocksOfInverse(t.H.inverse());
    const InverseBlocks paper = paperSchurBlocks(t, par.pointMass, schurSsCorrected(t, par.pointMass));
    worst = std::max({worst, relativeDifference(direct.ss, paper.ss), relativeDifference(direct.ps, paper.ps),
                      relativeDifference(direct.sp, paper.sp), relativeDifference(direct.pp, paper.pp)});
    // (39) also claims H_sp = H_ps^T, and the coding note below (40) that
    // H_pp = I/m_p + H_ps H_ss^-1 H_sp.
    worst = std::max(worst, relativeDifference<Mat32>(paper.sp, paper.ps.transpose()));
    const Eigen::Matrix2d note = Eigen::Matrix2d::Identity() / par.pointMass + paper.ps * paper.ss.inverse() * paper.sp;
    worst = std::max(worst, relativeDifference(note, paper.pp));
  }
  std::printf("[measured] corrected (37) with (38)-(40) vs inverse: %.2e\n", worst);
  EXPECT_LT(worst, kRoundOff);
}

TEST(RollingDynamics, PrintedEquation37IsWrong) {
  // As printed, J_c + m_p A k k^T A flips the sign of the rank-one term (A is
  // skew, so A k k^T A = -(A k)(A k)^T). A k = rho_p x k + R e_z x k vanishes
  // only for p = 0 on an upright face, which random states never hit; the
  // printed form must then disagree with the true block beyond round-off.
  const HemisphereParams par = paperParams();
  std::mt19937_64 rng(370);
  double smallest = 1e300;
  for (int i = 0; i < kSamples; ++i) {
    const PaperTerms t = paperTerms(par, randomState(rng, par));
    const Mat3 direct = blocksOfInverse(t.H.inverse()).ss;
    smallest = std::min(smallest, relativeDifference(direct, schurSsPrinted(t, par.pointMass)));
  }
  std::printf("[measured] printed (37): smallest relative difference %.2e\n", smallest);
  // The flipped term 2 m_p |A k|^2 is comparable to J_c (~m_s R^2) except
  // near p = 0 upright, so the difference is 1e-2..1; 1e-3 is still 1e8 times
  // round-off, so no state can pass by accident.
  EXPECT_GT(smallest, 1e-3);
}

}  // namespace
}  // namespace hemiroll::test
