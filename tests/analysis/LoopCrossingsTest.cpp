// engine/analysis LoopCrossings: the helix's loop crossings from cheap
// angles, to the bit of the construction from libm's atan2 everywhere.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "engine/analysis/Filters.h"
#include "engine/analysis/LoopCrossings.h"

namespace hemiroll::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

// HelixDetector's construction before issue 32 (an atan2 per sample), kept
// here as the reference every decision of loopCrossings must reproduce.
std::vector<double> referenceCrossings(const std::vector<double>& tx, const std::vector<double>& ty,
                                       const std::vector<double>& vx, const std::vector<double>& vy, std::size_t h,
                                       int sense) {
  auto headings = [](const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> a(x.size());
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = std::atan2(y[i], x[i]);
    return unwrapAngles(a);
  };
  const std::vector<double> tangent = headings(tx, ty), travel = headings(vx, vy);
  std::vector<double> relative(travel.size());
  for (std::size_t i = 0; i < relative.size(); ++i) {
    const std::size_t k = std::min(i < h ? 0 : i - h, tangent.size() - 1);
    relative[i] = travel[i] - tangent[k];
  }
  relative = unwrapAngles(relative);
  const double shift = -2.0 * kPi * std::round(relative.front() / (2.0 * kPi));
  for (double& r : relative) r += shift;
  const double s = sense;
  double target = s * kPi * (2.0 * std::floor((s * relative.front() / kPi + 1.0) / 2.0) + 1.0);
  std::vector<double> positions;
  for (std::size_t i = 1; i < relative.size(); ++i) {
    if (s * (relative[i] - target) < 0.0) continue;
    const double w = (target - relative[i - 1]) / (relative[i] - relative[i - 1]);
    positions.push_back(static_cast<double>(i - 1) + std::clamp(w, 0.0, 1.0));
    target += s * 2.0 * kPi;
  }
  return positions;
}

std::vector<std::uint64_t> bitsOf(const std::vector<double>& v) {
  std::vector<std::uint64_t> bits;
  for (const double x : v) bits.push_back(std::bit_cast<std::uint64_t>(x));
  return bits;
}

// Within its bound everywhere: a scan of the reduced argument (the error
// changes by less than the spacing between scanned points), and random
// directions in every quarter, on the axes and with signed zeros.
TEST(LoopCrossings, CheapAtan2IsWithinItsBound) {
  double worst = 0.0;
  for (int i = 0; i <= 2'000'000; ++i) {
    const double t = i / 2'000'000.0;
    worst = std::max({worst, std::abs(cheapAtan2(t, 1.0) - std::atan2(t, 1.0)),
                      std::abs(cheapAtan2(1.0, t) - std::atan2(1.0, t))});
  }
  EXPECT_LE(worst, kCheapAtan2Error);
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-300, 300);
  for (int i = 0; i < 200'000; ++i) {
    const double x = std::ldexp(unit(rng), scale(rng) / 10), y = std::ldexp(unit(rng), scale(rng) / 10);
    EXPECT_LE(std::abs(cheapAtan2(y, x) - std::atan2(y, x)), kCheapAtan2Error) << y << ", " << x;
  }
  for (const double x : {-2.0, -0.0, 0.0, 3.0})
    for (const double y : {-5.0, -0.0, 0.0, 1.0}) {
      if (x == 0.0 && y == 0.0) EXPECT_TRUE(std::isnan(cheapAtan2(y, x)));
      else EXPECT_LE(std::abs(cheapAtan2(y, x) - std::atan2(y, x)), kCheapAtan2Error) << y << ", " << x;
    }
}

// A tangent turning slowly and a travel looping about it, with samples put
// within 1e-4 rad (a few cheap errors: fixed, so that a bound made too
// small fails here) of every decision's boundary: relative
// directions at an odd multiple of pi (a crossing's side), and heading steps
// of pi (a turn of the unwrapping, of both headings and of their difference).
struct Trace {
  std::vector<double> tx, ty, vx, vy;
};
Trace loopingTrace(std::mt19937_64& rng, std::size_t n, std::size_t h, int sense) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), near(-1e-4, 1e-4);
  const std::size_t m = n > 2 * h ? n - 2 * h : 1;
  Trace t;
  std::vector<double> tangent(m);
  double heading = 2.0 * kPi * unit(rng);
  for (std::size_t k = 0; k < m; ++k) {
    heading += 0.05 * (unit(rng) - 0.5);
    if (unit(rng) < 0.02) heading += kPi + near(rng);  // a step of pi in the tangent
    tangent[k] = heading;
    const double r = 0.1 + unit(rng);
    t.tx.push_back(r * std::cos(heading)), t.ty.push_back(r * std::sin(heading));
  }
  double phase = kPi * (2.0 * unit(rng) - 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = unit(rng);
    if (u < 0.1) {
      // Onto the odd multiple of pi nearest to it, give or take a few errors.
      phase = kPi * (2.0 * std::round((phase - kPi) / (2.0 * kPi)) + 1.0) + near(rng);
    } else if (u < 0.13) {
      phase += kPi + near(rng);  // a step of pi in the travel
    } else {
      phase += sense * (0.4 * unit(rng) - 0.05);
    }
    const double angle = tangent[std::min(i < h ? 0 : i - h, m - 1)] + phase;
    const double r = 0.01 + unit(rng);
    t.vx.push_back(r * std::cos(angle)), t.vy.push_back(r * std::sin(angle));
  }
  return t;
}

TEST(LoopCrossings, AreTheExactConstructionsToTheBit) {
  std::mt19937_64 rng(3232);
  std::size_t crossings = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 2 + rng() % 3000, h = rng() % 40;
    const int sense = trial % 2 == 0 ? 1 : -1;
    const Trace t = loopingTrace(rng, n, h, sense);
    const std::vector<double> expected = referenceCrossings(t.tx, t.ty, t.vx, t.vy, h, sense);
    ASSERT_EQ(bitsOf(loopCrossings(t.tx, t.ty, t.vx, t.vy, h, sense)), bitsOf(expected))
        << "trial " << trial << ", " << n << " samples, lag " << h;
    crossings += expected.size();
  }
  EXPECT_GT(crossings, 5'000u);  // the traces do loop
}

// Where a direction is (0, 0), signed zeros, infinite or NaN, the cheap angle
// gives no decision and libm's is taken: still the same bits (NaN's included).
TEST(LoopCrossings, DegenerateDirectionsGiveTheExactConstructions) {
  std::mt19937_64 rng(77);
  const double specials[] = {0.0, -0.0, std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(),
                             1e-300, -1.0};
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 2 + rng() % 300, h = rng() % 10;
    const int sense = trial % 2 == 0 ? 1 : -1;
    Trace t = loopingTrace(rng, n, h, sense);
    for (int j = 0; j < 3; ++j) {
      std::vector<double>& column = *std::vector<std::vector<double>*>{&t.tx, &t.ty, &t.vx, &t.vy}[rng() % 4];
      column[rng() % column.size()] = specials[rng() % std::size(specials)];
    }
    ASSERT_EQ(bitsOf(loopCrossings(t.tx, t.ty, t.vx, t.vy, h, sense)),
              bitsOf(referenceCrossings(t.tx, t.ty, t.vx, t.vy, h, sense)))
        << "trial " << trial;
  }
}

}  // namespace
}  // namespace hemiroll::analysis
