#pragma once
// Eqs. (23)-(40), (46)-(47) of the paper, transcribed literally (with the
// corrections of physics-notes.md applied only where a function says so), as
// the reference the engine's reduced form is checked against.

#include <Eigen/Core>

#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {

using Mat5 = Eigen::Matrix<double, 5, 5>;
using Vec5 = Eigen::Matrix<double, 5, 1>;
using Mat32 = Eigen::Matrix<double, 3, 2>;
using Mat23 = Eigen::Matrix<double, 2, 3>;

// All the quantities of Sec. 2.2 and 3.1 at one state, in the base frame.
struct PaperTerms {
  Mat3 R;        // eq. (6)
  Mat32 RN;      // R N, eq. (16)
  Vec3 k;        // k_o
  Vec3 rhoP, rhoPDot, rhoC, rhoS;
  Mat3 A;        // hat(rho_p - rho_c)
  Mat3 Jc;       // inertia about the contact, below eq. (21)
  Mat5 H;        // eqs. (24)-(27)
  Vec2 hpFree;   // eq. (28) with f = 0
  Vec3 hsFree;   // eq. (29) with f = 0
};

// force3 is the force on the mass point in the base frame; in M1 and for an
// in-face f it is R N f. Eqs. (28)-(29) take f = N^T R^T F in h_p and F in
// h_s (Sec. 3.2, M2): for an in-face F this is exactly (28)-(29).
PaperTerms paperTerms(const HemisphereParams& params, const State12& x);
Vec5 paperRightHandSide(const PaperTerms& t, const Vec3& force3);
// [p''; w'] from the 5x5 system (30) solved by LU.
Vec5 solveFiveByFive(const PaperTerms& t, const Vec3& force3);

// Blocks of the inverse, eq. (32): pp (2x2), ps (2x3), sp (3x2), ss (3x3).
struct InverseBlocks {
  Eigen::Matrix2d pp;
  Mat23 ps;
  Mat32 sp;
  Mat3 ss;
};
InverseBlocks blocksOfInverse(const Mat5& inverse);
InverseBlocks schurBlocksGeneral(const PaperTerms& t);  // eqs. (33)-(36)
Mat3 schurSsCorrected(const PaperTerms& t, double pointMass);  // eq. (37): J_c + m_p A^T k k^T A
Mat3 schurSsPrinted(const PaperTerms& t, double pointMass);    // eq. (37) as printed: J_c + m_p A k k^T A
// Eqs. (38)-(40) built on a given H_ss-block (the corrected one, in the tests).
InverseBlocks paperSchurBlocks(const PaperTerms& t, double pointMass, const Mat3& ssBlock);

// Eq. (47): w' for the prescribed drive, and eq. (46): the f that realises p''.
Vec3 prescribedOmegaDot(const PaperTerms& t);
Vec2 prescribedForce(const PaperTerms& t, const Vec2& pDDot, const Vec3& omegaDot);

}  // namespace hemiroll::test
