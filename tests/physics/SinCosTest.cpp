// SinCos.h: the engine's own sine and cosine against libm.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "engine/physics/SinCos.h"
#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {
namespace {

// Error in units of the last place of the libm value (libm is itself within
// ~0.5..1 ulp of the true value).
double ulpsOff(double mine, double libm) {
  const double ulp = std::nextafter(std::abs(libm), INFINITY) - std::abs(libm);
  return std::abs(mine - libm) / ulp;
}

TEST(SinCos, AgreesWithLibmAcrossTheRanges) {
  std::mt19937_64 rng(271828);
  double worstSmall = 0.0, worstAbs = 0.0;
  for (int i = 0; i < 200000; ++i) {
    // Angles as they occur (|x| < 10 rad), and psi after long spinning runs.
    const double x = i % 2 ? uniform(rng, -10.0, 10.0) : uniform(rng, -1e5, 1e5);
    const physics::SinCos sc = physics::sinCos(x);
    worstAbs = std::max({worstAbs, std::abs(sc.sin - std::sin(x)), std::abs(sc.cos - std::cos(x))});
    if (std::abs(std::sin(x)) > 1e-3) worstSmall = std::max(worstSmall, ulpsOff(sc.sin, std::sin(x)));
    if (std::abs(std::cos(x)) > 1e-3) worstSmall = std::max(worstSmall, ulpsOff(sc.cos, std::cos(x)));
  }
  std::printf("[measured] sinCos vs libm: max %.2f ulp (|value| > 1e-3), max abs %.2e\n", worstSmall, worstAbs);
  // A Taylor kernel truncated below 1e-17 plus an exact reduction: a couple of
  // ulps at most; the absolute error must stay at eps level everywhere
  // (near zeros of sin/cos the ulp shrinks but the physics sees absolute error).
  EXPECT_LT(worstSmall, 4.0);
  EXPECT_LT(worstAbs, 2.0 * kEps);
}

TEST(SinCos, ExactAtZeroAndOddEvenSymmetry) {
  EXPECT_EQ(physics::sinCos(0.0).sin, 0.0);
  EXPECT_EQ(physics::sinCos(0.0).cos, 1.0);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 10000; ++i) {
    const double x = uniform(rng, 0.0, 100.0);
    EXPECT_EQ(physics::sinCos(-x).sin, -physics::sinCos(x).sin);
    EXPECT_EQ(physics::sinCos(-x).cos, physics::sinCos(x).cos);
  }
}

// sinCos2 (two angles in the lanes of one register) and sinCos (sine and
// cosine polynomials of one angle in the two lanes) promise the same bits for
// an angle, whichever computes it: the physics calls both.
TEST(SinCos, PairedFormsGiveTheBitsOfEachOther) {
  std::mt19937_64 rng(5);
  auto sameBits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (int i = 0; i < 200000; ++i) {
    // Small angles (no reduction), the reduction range, and pairs mixing the two.
    const double a = i % 3 == 0 ? uniform(rng, -0.78, 0.78) : uniform(rng, -1e3, 1e3);
    const double b = i % 2 == 0 ? uniform(rng, -0.78, 0.78) : uniform(rng, -20.0, 20.0);
    physics::SinCos pa, pb;
    physics::sinCos2(a, b, pa, pb);
    const physics::SinCos sa = physics::sinCos(a), sb = physics::sinCos(b);
    ASSERT_TRUE(sameBits(pa.sin, sa.sin) && sameBits(pa.cos, sa.cos)) << "angle " << a;
    ASSERT_TRUE(sameBits(pb.sin, sb.sin) && sameBits(pb.cos, sb.cos)) << "angle " << b;
  }
}

// sinCosLanes (the batched integrator's) takes each lane's quadrant from the
// bits of the rounding shift's sum; it must agree with sinCos's integer
// conversion for every quadrant, both signs and the whole reduction range
// (|n| up to 1e6).
TEST(SinCos, LanesGiveTheBitsOfSinCosOverTheReductionRange) {
  typedef double Lanes4 __attribute__((vector_size(32)));
  std::mt19937_64 rng(32);
  auto sameBits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (int i = 0; i < 100000; ++i) {
    const double limit = i % 3 == 0 ? 10.0 : i % 3 == 1 ? 1e3 : 1.59e6;
    const Lanes4 x = {uniform(rng, -limit, limit), uniform(rng, -limit, limit), uniform(rng, -0.78, 0.78),
                      uniform(rng, -limit, limit)};
    const physics::SinCosOf<Lanes4> lanes = physics::sinCosLanes(x);
    for (int lane = 0; lane < 4; ++lane) {
      const physics::SinCos one = physics::sinCos(x[lane]);
      ASSERT_TRUE(sameBits(lanes.sin[lane], one.sin) && sameBits(lanes.cos[lane], one.cos)) << "angle " << x[lane];
    }
  }
}

// sinCosLanes decides for the whole vector: every lane small (no reduction),
// every lane in the exact range (reduced), or lane by lane. One lane off the
// others' case, at each position and each width, must move the whole vector
// to the wider path; angles at the edges of the small range (0.78, ±0) too.
template <class T>
void expectEveryLaneDecidesTheVectorsPath() {
  constexpr int kLanes = sizeof(T) / sizeof(double);
  auto sameBits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  const double small[] = {0.0, -0.0, 1e-300, -0.5, 0.3, std::nextafter(0.78, 0.0), -std::nextafter(0.78, 0.0), 0.1};
  // Each outside the small range: 1.0 and -2.5 need the reduction (the kernel
  // alone gives other bits on them), +-1e300 and NaN libm; +-0.78 is the edge.
  const double odd[] = {0.78, -0.78, 1.0, -2.5, 1e300, -1e300, NAN};
  for (int position = 0; position < kLanes; ++position) {
    for (double other : odd) {
      for (bool allSmall : {true, false}) {
        T x;
        for (int lane = 0; lane < kLanes; ++lane) x[lane] = small[(lane + position) % 8];
        if (!allSmall) x[position] = other;
        const physics::SinCosOf<T> lanes = physics::sinCosLanes(x);
        for (int lane = 0; lane < kLanes; ++lane) {
          const physics::SinCos one = physics::sinCos(x[lane]);
          if (std::isnan(x[lane])) {
            ASSERT_TRUE(std::isnan(lanes.sin[lane]) && std::isnan(lanes.cos[lane]));
            continue;
          }
          ASSERT_TRUE(sameBits(lanes.sin[lane], one.sin) && sameBits(lanes.cos[lane], one.cos))
              << kLanes << " lanes, lane " << lane << ", angle " << x[lane] << " beside " << other << " at lane "
              << position;
        }
      }
    }
  }
}

TEST(SinCos, LanesTakeTheirPathFromEveryLane) {
  typedef double Lanes2 __attribute__((vector_size(16)));
  typedef double Lanes4 __attribute__((vector_size(32)));
  typedef double Lanes8 __attribute__((vector_size(64)));
  expectEveryLaneDecidesTheVectorsPath<Lanes2>();
  expectEveryLaneDecidesTheVectorsPath<Lanes4>();
  expectEveryLaneDecidesTheVectorsPath<Lanes8>();
}

TEST(SinCos, FallsBackBeyondTheExactReduction) {
  for (double x : {2e6, -3.3e7, 1e300}) {
    EXPECT_EQ(physics::sinCos(x).sin, std::sin(x));
    EXPECT_EQ(physics::sinCos(x).cos, std::cos(x));
  }
  EXPECT_TRUE(std::isnan(physics::sinCos(NAN).sin));
}

}  // namespace
}  // namespace hemiroll::test
