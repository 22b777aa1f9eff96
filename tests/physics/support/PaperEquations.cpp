#include "tests/physics/support/PaperEquations.h"

#include <Eigen/LU>

namespace hemiroll::test {

namespace {
Mat32 projectionN() {
  Mat32 N;
  N << 1.0, 0.0, 0.0, 1.0, 0.0, 0.0;  // eq. (16)
  return N;
}
}  // namespace

PaperTerms paperTerms(const HemisphereParams& par, const State12& x) {
  const double mp = par.pointMass, ms = par.shellMass, a = par.radius;
  const Vec3 g(0.0, 0.0, -par.gravity);
  const Vec2 p = x.segment<2>(0), pd = x.segment<2>(2);
  const Vec3 w = x.segment<3>(4);

  PaperTerms t;
  t.R = orientationFromAngles(x(9), x(10), x(11));
  t.RN = t.R * projectionN();
  t.k = t.R.col(2);
  t.rhoP = t.RN * p;
  t.rhoPDot = t.RN * pd;
  t.rhoC = -a * Vec3::UnitZ();
  t.rhoS = -3.0 / 8.0 * a * t.k;
  t.A = hat(t.rhoP - t.rhoC);
  const Mat3 Jo = 0.4 * ms * a * a * Mat3::Identity();
  const Mat3 S = hat(t.rhoS), C = hat(t.rhoC);
  t.Jc = Jo + ms * (S * C + C * S - C * C);

  t.H.setZero();
  t.H.block<2, 2>(0, 0) = mp * Eigen::Matrix2d::Identity();       // (24)
  t.H.block<2, 3>(0, 2) = -mp * t.RN.transpose() * t.A;           // (25)
  t.H.block<3, 2>(2, 0) = mp * t.A * t.RN;                        // (26)
  t.H.block<3, 3>(2, 2) = t.Jc - mp * t.A * t.A;                  // (27)

  const Vec3 bias = w.cross(w.cross(t.rhoP)) + 2.0 * w.cross(t.rhoPDot);
  t.hpFree = -mp * t.RN.transpose() * (bias - g);                 // (28), f = 0
  t.hsFree = -mp * (t.rhoP - t.rhoC).cross(bias) + t.rhoC.cross(w.cross(w.cross(ms * t.rhoS))) +
             (ms * t.rhoS + mp * t.rhoP).cross(g);                // (29), f = 0
  return t;
}

Vec5 paperRightHandSide(const PaperTerms& t, const Vec3& F) {
  Vec5 h;
  h.head<2>() = t.hpFree + t.RN.transpose() * F;
  h.tail<3>() = t.hsFree + (t.A * F);
  return h;
}

Vec5 solveFiveByFive(const PaperTerms& t, const Vec3& F) { return t.H.partialPivLu().solve(paperRightHandSide(t, F)); }

InverseBlocks blocksOfInverse(const Mat5& inv) {
  return {inv.block<2, 2>(0, 0), inv.block<2, 3>(0, 2), inv.block<3, 2>(2, 0), inv.block<3, 3>(2, 2)};
}

InverseBlocks schurBlocksGeneral(const PaperTerms& t) {
  const Eigen::Matrix2d Hpp = t.H.block<2, 2>(0, 0);
  const Mat23 Hps = t.H.block<2, 3>(0, 2);
  const Mat32 Hsp = t.H.block<3, 2>(2, 0);
  const Mat3 Hss = t.H.block<3, 3>(2, 2);
  const Eigen::Matrix2d HppInv = Hpp.inverse();
  InverseBlocks b;
  b.ss = (Hss - Hsp * HppInv * Hps).inverse();           // (33)
  b.ps = -HppInv * Hps * b.ss;                           // (34)
  b.sp = -b.ss * Hsp * HppInv;                           // (35)
  b.pp = HppInv + HppInv * Hps * b.ss * Hsp * HppInv;    // (36)
  return b;
}

Mat3 schurSsCorrected(const PaperTerms& t, double mp) {
  return (t.Jc + mp * t.A.transpose() * t.k * t.k.transpose() * t.A).inverse();
}

Mat3 schurSsPrinted(const PaperTerms& t, double mp) {
  return (t.Jc + mp * t.A * t.k * t.k.transpose() * t.A).inverse();
}

InverseBlocks paperSchurBlocks(const PaperTerms& t, double mp, const Mat3& ss) {
  InverseBlocks b;
  b.ss = ss;
  b.ps = -t.RN.transpose() * t.A.transpose() * ss;                                          // (38)
  b.sp = -ss * t.A * t.RN;                                                                  // (39)
  b.pp = Eigen::Matrix2d::Identity() / mp + t.RN.transpose() * t.A.transpose() * ss * t.A * t.RN;  // (40)
  return b;
}

Vec3 prescribedOmegaDot(const PaperTerms& t) {
  const Mat23 Hps = t.H.block<2, 3>(0, 2);
  const Mat3 Hss = t.H.block<3, 3>(2, 2);
  const Mat3 lhs = Hss - t.A * t.RN * Hps;                 // (47), left factor
  const Vec3 rhs = t.hsFree - t.A * t.RN * t.hpFree;       // (47), right factor
  return lhs.partialPivLu().solve(rhs);
}

Vec2 prescribedForce(const PaperTerms& t, const Vec2& pDDot, const Vec3& omegaDot) {
  // (46): H_pp p'' + H_ps w' = f + h_p(f = 0).
  return t.H.block<2, 2>(0, 0) * pDDot + t.H.block<2, 3>(0, 2) * omegaDot - t.hpFree;
}

}  // namespace hemiroll::test
