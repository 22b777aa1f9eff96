#pragma once
// sin and cos of one angle together, computed by the engine itself.
//
// Why not std::sin/std::cos: the three angles of the orientation are the
// largest single cost of a right-hand side (libm's sincos is ~110 instructions
// a call, a third of an evaluation), and libm's last bit differs between C
// library versions, which would break bit-for-bit replays across machines.
// This version is a Cody-Waite reduction by pi/2 (three-part constant, exact
// for |x| < 2^20 pi/2) followed by Taylor polynomials on [-pi/4, pi/4],
// truncated where the next term is below 1e-17. Accuracy is checked against
// libm in tests/physics/SinCosTest.cpp. Beyond the exact reduction range
// (|x| > 1.6e6 rad, far beyond any physical run) it defers to libm.

#include <cmath>

namespace hemiroll::physics {

template <class T>
struct SinCosOf {
  T sin, cos;
};
using SinCos = SinCosOf<double>;

namespace detail {
// pi/2 split into 33 + 33 + 53 significant bits: n * kPiOver2Hi and
// n * kPiOver2Mid are exact for |n| < 2^20.
inline constexpr double kPiOver2Hi = 0x1.921fb544p+0;
inline constexpr double kPiOver2Mid = 0x1.0b4611a6p-34;
inline constexpr double kPiOver2Lo = 0x1.3198a2e037073p-69;
inline constexpr double kTwoOverPi = 0.6366197723675814;
inline constexpr double kExactReductionLimit = 1.6e6;
inline constexpr double kRoundingShift = 0x1.8p52;
// Below this the reduction gives n = 0 and r = x exactly, so skipping it
// changes no bit and takes the reduction off the dependent chain (tilts are
// mostly small).
inline constexpr double kNoReductionLimit = 0.78;

typedef double Lanes __attribute__((vector_size(16)));  // two doubles, one SSE2 register

// Taylor series on |r| <= pi/4 (plus a little slack from the rounding of n),
// truncated where the next term is below 1e-17 of the result:
//   sin r = r + r z P(z),  cos r = 1 - z/2 + z^2 Q(z),  z = r^2.
inline constexpr double kSinCoefficients[8] = {-1.0 / 6,
                                               1.0 / 120,
                                               -1.0 / 5040,
                                               2.7557319223985893e-06,
                                               -2.505210838544172e-08,
                                               1.6059043836821613e-10,
                                               -7.647163731819816e-13,
                                               2.8114572543455206e-15};
inline constexpr double kCosCoefficients[8] = {1.0 / 24,
                                               -1.0 / 720,
                                               2.48015873015873e-05,
                                               -2.755731922398589e-07,
                                               2.08767569878681e-09,
                                               -1.1470745597729725e-11,
                                               4.779477332387385e-14,
                                               -1.5619206968586225e-16};

// P or Q by Estrin's scheme rather than Horner's: the right-hand side is
// latency-bound and this halves the dependent chain (about 20 instead of 48
// cycles). The coefficients are scalars (the same polynomial in every lane of
// T) or lanes themselves (a different polynomial in each lane): either way
// every lane sees the same operations in the same order, so a value has the
// same bits whichever form computed it.
template <class T, class C>
inline T estrin8(T z, T z2, T z4, const C (&c)[8]) {
  return ((c[0] + z * c[1]) + z2 * (c[2] + z * c[3])) + z4 * ((c[4] + z * c[5]) + z2 * (c[6] + z * c[7]));
}

// The last steps of the two kernels, given P or Q. For the cosine, 1 - z/2
// loses bits when z/2 is near 1/4..1/2; take the exact part first.
template <class T>
inline T sinFromPolynomial(T r, T z, T p) {
  return r + r * z * p;
}
template <class T>
inline T cosFromPolynomial(T z, T z2, T q) {
  const T half = 0.5 * z;
  const T w = 1.0 - half;
  return w + (((1.0 - w) - half) + z2 * q);
}

// sin and cos of the same angles in every lane of T (one angle, or a pair).
template <class T>
inline T sinKernel(T r) {
  const T z = r * r, z2 = z * z, z4 = z2 * z2;
  return sinFromPolynomial(r, z, estrin8(z, z2, z4, kSinCoefficients));
}
template <class T>
inline T cosKernel(T r) {
  const T z = r * r, z2 = z * z, z4 = z2 * z2;
  return cosFromPolynomial(z, z2, estrin8(z, z2, z4, kCosCoefficients));
}

// sin and cos of one angle, P in one lane and Q in the other: they share z
// and its powers, and one register does the work of two scalar polynomials.
inline constexpr Lanes kSinCosCoefficients[8] = {
    {kSinCoefficients[0], kCosCoefficients[0]}, {kSinCoefficients[1], kCosCoefficients[1]},
    {kSinCoefficients[2], kCosCoefficients[2]}, {kSinCoefficients[3], kCosCoefficients[3]},
    {kSinCoefficients[4], kCosCoefficients[4]}, {kSinCoefficients[5], kCosCoefficients[5]},
    {kSinCoefficients[6], kCosCoefficients[6]}, {kSinCoefficients[7], kCosCoefficients[7]}};
inline SinCos sinCosKernel(double r) {
  const double z = r * r, z2 = z * z, z4 = z2 * z2;
  const Lanes pq = estrin8(Lanes{z, z}, Lanes{z2, z2}, Lanes{z4, z4}, kSinCosCoefficients);
  return {sinFromPolynomial(r, z, pq[0]), cosFromPolynomial(z, z2, pq[1])};
}
}  // namespace detail

inline SinCos sinCos(double x) {
  using namespace detail;
  if (std::fabs(x) < kNoReductionLimit) return sinCosKernel(x);
  if (!(std::fabs(x) < kExactReductionLimit)) return {std::sin(x), std::cos(x)};  // also NaN, Inf
  // Round to nearest by the 1.5 * 2^52 shift: no libm call, same bits
  // everywhere (the build forbids fast-math, so the sum is not folded away).
  const double n = (x * kTwoOverPi + kRoundingShift) - kRoundingShift;
  const double r = ((x - n * kPiOver2Hi) - n * kPiOver2Mid) - n * kPiOver2Lo;
  const SinCos k = sinCosKernel(r);
  const double s = k.sin, c = k.cos;
  switch (static_cast<long>(n) & 3) {
    case 0: return {s, c};
    case 1: return {c, -s};
    case 2: return {-s, -c};
    default: return {-c, s};
  }
}

namespace detail {
// The integer vector with T's lanes (a member typedef: GCC drops a dependent
// vector_size from a typedef local to a function template).
template <class T>
struct LaneIntsOf {
  typedef long long type __attribute__((vector_size(sizeof(T))));
};

// sin and cos of every lane of T, |x| < kExactReductionLimit in each: the
// Cody-Waite reduction, the kernels, and the quadrant's swap and signs as
// sinCos's switch makes them.
template <class T>
inline SinCosOf<T> reducedSinCos(T x) {
  using LaneInts = typename LaneIntsOf<T>::type;
  const T shifted = x * kTwoOverPi + kRoundingShift;
  const T n = shifted - kRoundingShift;
  const T r = ((x - n * kPiOver2Hi) - n * kPiOver2Mid) - n * kPiOver2Lo;
  const T s = sinKernel(r), c = cosKernel(r);
  // n mod 4 from the shifted sum's bits: its exponent puts the unit in the
  // last mantissa bit, so the mantissa is 2^51 + n (|n| < 2^51 here), whose
  // low two bits are n & 3. A bit cast, where converting n to integers has
  // no vector instruction below AVX-512DQ (GCC converted lane by lane).
  const LaneInts quadrant = __builtin_bit_cast(LaneInts, shifted) & 3;
  const LaneInts swap = (quadrant & 1) != 0;
  const T sinAbs = swap ? c : s, cosAbs = swap ? s : c;
  return {(quadrant & 2) != 0 ? -sinAbs : sinAbs, ((quadrant + 1) & 2) != 0 ? -cosAbs : cosAbs};
}
}  // namespace detail

// Two angles at once, each with exactly the bits sinCos gives it: the same
// operations in the same order, in the two lanes of an SSE2 register (GCC and
// Clang vector extensions). The orientation needs three per evaluation.
inline void sinCos2(double a, double b, SinCos& outA, SinCos& outB) {
  using namespace detail;
  const Lanes x = {a, b};
  // The common case first (tilts are mostly small); NaN fails both tests.
  if (std::fabs(a) < kNoReductionLimit && std::fabs(b) < kNoReductionLimit) {
    const Lanes s = sinKernel(x), c = cosKernel(x);
    outA = {s[0], c[0]};
    outB = {s[1], c[1]};
    return;
  }
  if (!(std::fabs(a) < kExactReductionLimit && std::fabs(b) < kExactReductionLimit)) {
    outA = sinCos(a);
    outB = sinCos(b);
    return;
  }
  const SinCosOf<Lanes> both = reducedSinCos(x);
  outA = {both.sin[0], both.cos[0]};
  outB = {both.sin[1], both.cos[1]};
}

namespace detail {
// Whether every lane of a comparison's mask (0 or -1 per lane) is set: the
// halves ANDed down to two lanes, then one test. Testing lane by lane, GCC
// extracted each lane to a general register and branched on it (about 20
// instructions and 8 branches at 8 lanes, in each of a step's sinCosLanes).
template <class M>
inline bool allLanesSet(M m) {
  constexpr int kLanes = sizeof(M) / 8;
  if constexpr (kLanes == 1) {
    return m[0] != 0;
  } else if constexpr (kLanes == 2) {
    return (m[0] & m[1]) != 0;
  } else if constexpr (kLanes == 4) {
    return allLanesSet(__builtin_shufflevector(m, m, 0, 1) & __builtin_shufflevector(m, m, 2, 3));
  } else {
    static_assert(kLanes == 8, "2, 4 or 8 lanes");
    return allLanesSet(__builtin_shufflevector(m, m, 0, 1, 2, 3) & __builtin_shufflevector(m, m, 4, 5, 6, 7));
  }
}
}  // namespace detail

// Each lane of T (a GCC vector of doubles, BatchedRk4.h) with exactly the
// bits sinCos gives that lane's angle. Where every lane is below 0.78 it
// skips the reduction as sinCos does (the reduction would give n = 0 and
// r = x exactly, quadrant 0: no bit changes); else it reduces every lane,
// with sinCos2's reduction and quadrant logic.
template <class T>
inline SinCosOf<T> sinCosLanes(T x) {
  using namespace detail;
  using LaneInts = typename LaneIntsOf<T>::type;
  constexpr int kLanes = sizeof(T) / sizeof(double);
  // NaN fails the comparisons, so it takes the per-lane path as in sinCos.
  const LaneInts reducible = (x > -kExactReductionLimit) & (x < kExactReductionLimit);
  if (!allLanesSet(reducible)) {
    double sines[kLanes], cosines[kLanes];
    for (int lane = 0; lane < kLanes; ++lane) {
      const SinCos one = sinCos(x[lane]);
      sines[lane] = one.sin;
      cosines[lane] = one.cos;
    }
    SinCosOf<T> out;
    __builtin_memcpy(&out.sin, sines, sizeof out.sin);
    __builtin_memcpy(&out.cos, cosines, sizeof out.cos);
    return out;
  }
  // The frame's tilts are mostly small: the reduction off their chain.
  if (allLanesSet((x > -kNoReductionLimit) & (x < kNoReductionLimit))) return {sinKernel(x), cosKernel(x)};
  return reducedSinCos(x);
}

}  // namespace hemiroll::physics
