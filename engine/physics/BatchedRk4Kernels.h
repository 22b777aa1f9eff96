#pragma once
// The lockstep RK4 step of BatchedRk4.h over one lane type T: a double, or
// a GCC vector of 2, 4 or 8 doubles. Included only by the translation units
// that instantiate it (BatchedRk4Lanes*.cpp), each compiled for its
// instruction set; their entry points are [[gnu::flatten]], so nothing of
// this header is left out of line to be shared (and mixed up at link time)
// between instruction sets (tools/check-lane-objects.sh, the ctest physics.lane_objects_check, checks it).

#include <cmath>
#include <type_traits>

#include "engine/physics/BatchedRk4.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "engine/physics/RoseDrive.h"
#include "engine/physics/SinCos.h"

namespace hemiroll::physics::lanes {

template <class T>
constexpr int laneCount() {
  return static_cast<int>(sizeof(T) / sizeof(double));
}

template <class T>
inline T load(const double* p) {
  if constexpr (laneCount<T>() == 1) {
    return *p;
  } else {
    T v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
}
template <class T>
inline void store(double* p, T v) {
  if constexpr (laneCount<T>() == 1) *p = v;
  else __builtin_memcpy(p, &v, sizeof v);
}

// RK4 in RungeKutta4's operations and order (Integrator.h): each component is
// x + (h/6) ((k1 + 2 (k2 + k3)) + k4), the stages x + (h/2) k and x + h k.
template <int N, class T, class Rates>
inline void rk4StepOf(const Rates& rates, double t, T (&x)[N], double h) {
  const double half = 0.5 * h;
  T k1[N], k2[N], k3[N], k4[N], stage[N];
  rates(t, x, k1);
  for (int i = 0; i < N; ++i) stage[i] = x[i] + half * k1[i];
  rates(t + half, stage, k2);
  for (int i = 0; i < N; ++i) stage[i] = x[i] + half * k2[i];
  rates(t + half, stage, k3);
  for (int i = 0; i < N; ++i) stage[i] = x[i] + h * k3[i];
  rates(t + h, stage, k4);
  const double sixth = h / 6.0;
  for (int i = 0; i < N; ++i) x[i] += sixth * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
}

// Row r of the lanes first .. first + laneCount<T>() - 1.
template <class T>
inline T rowAt(const BatchView& v, int r, int first) {
  return load<T>(v.rows + static_cast<std::size_t>(r) * v.padded + first);
}

template <class T>
inline MassConstantsOf<T> massConstantsAt(const BatchView& v, int first) {
  auto at = [&](int r) { return rowAt<T>(v, r, first); };
  return {at(kPointMass), at(kShellMass), at(kRadius), at(kGravity), at(kComDepth), at(kShellMoment)};
}

// One step of the lanes first .. first + laneCount<T>() - 1; a retired lane
// keeps its state (the select is exact: it copies, it does not compute).
template <int N, class T, class Rates>
inline void stepGroup(const BatchView& v, int first, double t, double h, const Rates& rates) {
  T x[N];
  for (int i = 0; i < N; ++i) x[i] = load<T>(v.state + static_cast<std::size_t>(i) * v.padded + first);
  T next[N];
  for (int i = 0; i < N; ++i) next[i] = x[i];
  rk4StepOf<N>(rates, t, next, h);
  const T active = rowAt<T>(v, kActive, first);
  for (int i = 0; i < N; ++i) {
    const T kept = active != 0.0 ? next[i] : x[i];
    store(v.state + static_cast<std::size_t>(i) * v.padded + first, kept);
  }
}

// Skips groups whose lanes are all retired.
template <class T>
inline bool anyActive(const BatchView& v, int first) {
  const double* active = v.rows + static_cast<std::size_t>(kActive) * v.padded + first;
  for (int lane = 0; lane < laneCount<T>(); ++lane)
    if (active[lane] != 0.0) return true;
  return false;
}

// Whether every lane of a comparison's mask is set (a bool or int for plain
// doubles).
template <class M>
inline bool allSet(M m) {
  if constexpr (std::is_arithmetic_v<M>) return m != 0;
  else return detail::allLanesSet(m);
}

template <class T>
inline T absOf(T a) {
  if constexpr (laneCount<T>() == 1) {
    return std::fabs(a);
  } else {
    using LaneInts = typename detail::LaneIntsOf<T>::type;
    return __builtin_bit_cast(T, __builtin_bit_cast(LaneInts, a) & 0x7fffffffffffffffLL);
  }
}

// The lanes where PrescribedDriveSystem::domainEventWith takes its fast path
// for the state x with the mass point at p: InteriorCheck::surelyInside's
// comparisons on the same sums in the same order (no contraction into FMA:
// -ffp-contract=off), and x.allFinite() as Eigen computes it (x - x is 0
// exactly where x is finite, NaN where it is infinite or NaN).
template <class T>
inline auto surelyInsideMask(const T (&x)[8], const Real2Of<T>& p, T tiltSumBound, T faceBoundSquared) {
  using namespace body_slot;
  auto inside = (absOf(x[u_o]) + absOf(x[v_o]) <= tiltSumBound) & (p.x * p.x + p.y * p.y <= faceBoundSquared);
  for (int i = 0; i < 8; ++i) inside = inside & (x[i] - x[i] == 0.0);
  if constexpr (laneCount<T>() == 1) return inside != 0;
  else return inside;
}

// The same time to the bit: -0.0 and +0.0 give the rose different signs of
// zero, so == would not do; a NaN time never matches (it may mark "none").
inline bool sameTime(double a, double b) {
  return a == b && __builtin_bit_cast(unsigned long long, a) == __builtin_bit_cast(unsigned long long, b);
}

// The rose is sampled once per distinct time: RK4's stages 2 and 3 share
// t + h/2, and stage 1's t is usually the time the previous step kept its
// sample at (its grid end, BatchView::drive). Same time, same inputs, so
// the reused sample has the bits a new one would have.
//
// After the step, each lane's verdict for the domain check at t + h and at
// the grid end (RoseBatch::surelyInside); returns whether every active lane
// passed both.
template <class T>
inline bool roseStep(const BatchView& v, double t, double h) {
  auto driveRow = [&](int r, int first) { return v.drive + static_cast<std::size_t>(r) * v.padded + first; };
  bool everyActiveInside = true;
  for (int first = 0; first < v.padded; first += laneCount<T>()) {
    if (!anyActive<T>(v, first)) continue;
    const MassConstantsOf<T> c = massConstantsAt<T>(v, first);
    auto at = [&](int r) { return rowAt<T>(v, r, first); };
    const T r1 = at(kRoseR1), r2 = at(kRoseR2), k = at(kRoseK), omega = at(kRoseOmega);
    double sampleTime = *driveRow(kKeptSampleTime, first);
    Real2Of<T> p{load<T>(driveRow(kGridX, first)), load<T>(driveRow(kGridY, first))};
    Real2Of<T> pDot{load<T>(driveRow(kKeptPDotX, first)), load<T>(driveRow(kKeptPDotY, first))};
    auto sampleAt = [&](double tau) {
      if (sameTime(tau, sampleTime)) return;
      const RoseSampleOf<T> s = roseSampleOf(r1, r2, k, omega, tau);
      p = s.p;
      pDot = s.pDot;
      sampleTime = tau;
    };
    stepGroup<8, T>(v, first, t, h, [&](double tau, const T* x, T* dxdt) {
      sampleAt(tau);
      prescribedRatesOf(c, p, pDot, x, dxdt);
    });
    // p is now the last stage's, at t + h.
    const Real2Of<T> pEnd = p;
    store(driveRow(kEndX, first), p.x);
    store(driveRow(kEndY, first), p.y);
    // Where the grid time is not t + h to the bit, the rose once more there;
    // it is the sample kept for the next step, which begins there.
    sampleAt(v.gridEnd);
    store(driveRow(kGridX, first), p.x);
    store(driveRow(kGridY, first), p.y);
    store(driveRow(kKeptPDotX, first), pDot.x);
    store(driveRow(kKeptPDotY, first), pDot.y);
    for (int lane = 0; lane < laneCount<T>(); ++lane) driveRow(kKeptSampleTime, first)[lane] = sampleTime;
    T x[8];  // the states stepGroup has just stored (whole vectors: forwarded)
    for (int i = 0; i < 8; ++i) x[i] = load<T>(v.state + static_cast<std::size_t>(i) * v.padded + first);
    const T tiltSumBound = at(kTiltSumBound), faceBoundSquared = at(kFaceBoundSquared);
    const auto inside = surelyInsideMask(x, pEnd, tiltSumBound, faceBoundSquared) &
                        surelyInsideMask(x, p, tiltSumBound, faceBoundSquared);  // at t + h and at the grid end
    store(driveRow(kSurelyInside, first), inside ? broadcast<T>(1.0) : broadcast<T>(0.0));
    everyActiveInside = everyActiveInside && allSet(inside | (at(kActive) == 0.0));
  }
  return everyActiveInside;
}

template <class T>
inline void forceDrivenStep(const BatchView& v, double h) {
  for (int first = 0; first < v.padded; first += laneCount<T>()) {
    if (!anyActive<T>(v, first)) continue;
    const MassConstantsOf<T> c = massConstantsAt<T>(v, first);
    auto at = [&](int r) { return rowAt<T>(v, r, first); };
    if (v.method < 0) {
      const Real3Of<T> zero{broadcast<T>(0.0), broadcast<T>(0.0), broadcast<T>(0.0)};
      stepGroup<12, T>(v, first, 0.0, h, [&](double, const T* x, T* dxdt) {
        forceDrivenRatesOf(c, x, dxdt, [&](const auto&, const auto&) { return zero; });
      });
      continue;
    }
    const CouplingLawOf<T> law{static_cast<ForceMethod>(v.method), at(kStiffness), at(kDamping), at(kAlpha)};
    const Real3Of<T> proxyPosition{at(kProxyX), at(kProxyY), at(kProxyZ)};
    const Real3Of<T> proxyVelocity{at(kProxyVx), at(kProxyVy), at(kProxyVz)};
    stepGroup<12, T>(v, first, 0.0, h, [&](double, const T* x, T* dxdt) {
      // ForceDrivenSystem::inputForce's coupling case, on lanes.
      forceDrivenRatesOf(c, x, dxdt, [&](const RollingGeometryIn<HeadingFrameOf<T>>& g, const Real3Of<T>& omegaH) {
        const HeadingFrameOf<T>& f = g.frame;
        const Real3Of<T> centre{x[force_slot::u_a], x[force_slot::v_a], c.radius};
        const Real3Of<T> hand =
            handForceFromProxy(law, f.k, centre, g.rhoP, cross(omegaH, g.lever) + g.rhoPDot, proxyPosition,
                               proxyVelocity, [&f](const Real3Of<T>& w) { return f.toHeading(w); });
        return modelForceOf(law.method, f.k, hand);
      });
    });
  }
}

}  // namespace hemiroll::physics::lanes
