// engine/analysis Filters: centred moving average, local slope, unwrapping.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "engine/analysis/Filters.h"

namespace hemiroll::analysis {
namespace {

TEST(Filters, MovingAverageRemovesASinusoidOfItsOwnLength) {
  // 21 samples per period, window 2 * 10 + 1 = 21: the sine sums to zero.
  std::vector<double> v;
  for (int i = 0; i < 210; ++i) v.push_back(1.0 + std::sin(2.0 * std::numbers::pi * i / 21.0));
  const std::vector<double> a = movingAverage(v, 10);
  for (std::size_t i = 10; i + 10 < v.size(); ++i) EXPECT_NEAR(a[i], 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(a.front(), v.front());  // the window shrinks to one sample at the ends
}

TEST(Filters, LocalSlopeIsExactOnAQuadratic) {
  // A symmetric least-squares line through a parabola has the parabola's slope at the centre.
  std::vector<double> v;
  const double dt = 0.01;
  for (int i = 0; i < 500; ++i) v.push_back(0.3 * (i * dt) * (i * dt) - 2.0 * i * dt);
  const std::vector<double> s = localSlope(v, dt, 50);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_NEAR(s[i], 0.6 * i * dt - 2.0, i == 0 || i + 1 == v.size() ? 4e-3 : 1e-9);
}

// movingAverages runs two columns' sums side by side, and both divide
// their whole windows two at a time (issue 32): each must be the plain
// prefix-sum average's to the bit (this is it), ends included.
TEST(Filters, MovingAveragesAreTwoPlainMovingAverages) {
  auto plain = [](const std::vector<double>& v, std::size_t halfWidth) {
    const std::size_t n = v.size();
    std::vector<double> out(n), prefix(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + v[i];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t h = std::min({halfWidth, i, n - 1 - i});
      out[i] = (prefix[i + h + 1] - prefix[i - h]) / static_cast<double>(2 * h + 1);
    }
    return out;
  };
  std::mt19937 rng(34);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const std::size_t n : {0u, 1u, 2u, 7u, 8u, 1000u, 1001u}) {
    std::vector<double> x(n), y(n);
    double wx = 0.0, wy = 0.0;
    for (std::size_t i = 0; i < n; ++i) x[i] = wx += normal(rng), y[i] = wy += 1e-3 * normal(rng);
    for (const std::size_t halfWidth : {0u, 1u, 2u, 3u, 4u, 50u, 499u, 500u, 600u}) {
      const auto [ax, ay] = movingAverages(x, y, halfWidth);
      const std::vector<double> bx = plain(x, halfWidth), by = plain(y, halfWidth), cx = movingAverage(x, halfWidth);
      ASSERT_EQ(ax.size(), n);
      ASSERT_EQ(ay.size(), n);
      ASSERT_EQ(cx.size(), n);
      EXPECT_TRUE(n == 0 || std::memcmp(ax.data(), bx.data(), sizeof(double) * n) == 0) << "n " << n << " half width " << halfWidth;
      EXPECT_TRUE(n == 0 || std::memcmp(ay.data(), by.data(), sizeof(double) * n) == 0) << "n " << n << " half width " << halfWidth;
      EXPECT_TRUE(n == 0 || std::memcmp(cx.data(), bx.data(), sizeof(double) * n) == 0) << "n " << n << " half width " << halfWidth;
    }
  }
  const std::vector<double> longer(5, 1.0), shorter(3, 2.0);  // unequal: each on its own
  const auto [a, b] = movingAverages(longer, shorter, 1);
  EXPECT_EQ(a, movingAverage(longer, 1));
  EXPECT_EQ(b, movingAverage(shorter, 1));
}

// sweptAngleAbout and unwrapOffsetsAbout skip the atan2 of steps that
// cannot wrap (issue 32): they must give unwrapAngles' turn and angles to
// the bit, on paths that cross the -x axis
// many times (on it with dy = +0 and -0), stop at the centre (where atan2(0, -0) = pi), lie on the
// axes and diagonals, jump, or hold a NaN.
TEST(Filters, SweptAngleAndOffsetsAboutAreUnwrapAnglesOfEveryAtan2) {
  auto plain = [](const std::vector<double>& x, const std::vector<double>& y, double cx, double cy) {
    std::vector<double> a(x.size());
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = std::atan2(y[i] - cy, x[i] - cx);
    const std::vector<double> u = unwrapAngles(a);
    return u.empty() ? 0.0 : u.back() - u.front();
  };
  auto sameBits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  std::mt19937 rng(35);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 9);
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial % 97) * 7;
    const double cx = trial % 3 == 0 ? 0.0 : normal(rng), cy = trial % 5 == 0 ? 0.0 : normal(rng);
    const double rate = 0.3 * normal(rng), radius = std::abs(normal(rng)) + 1e-3;
    std::vector<double> x(n), y(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double phase = rate * static_cast<double>(i) + 0.05 * normal(rng);
      const double r = radius * (1.0 + 0.9 * std::sin(0.7 * static_cast<double>(i)));  // loops through the centre's side
      x[i] = cx + r * std::cos(phase), y[i] = cy + r * std::sin(phase);
      switch (pick(rng)) {
        case 0: x[i] = cx, y[i] = cy; break;                       // at the centre
        case 1: y[i] = cy; break;                                  // on the x axis (both sides)
        case 2: x[i] = cx; break;                                  // on the y axis
        case 3: y[i] = cy + (x[i] - cx); break;                    // on a diagonal
        case 4: x[i] = cx - std::abs(y[i] - cy) * 1e-17; break;    // just left of the y axis
        case 5: y[i] = cy == 0.0 ? -0.0 : cy; break;               // on the x axis, dy = -0 where it can be
        default: break;
      }
      if (trial % 50 == 7 && i == n / 2) x[i] = std::nan("");
    }
    const double fast = sweptAngleAbout(x, y, cx, cy), slow = plain(x, y, cx, cy);
    EXPECT_TRUE(sameBits(fast, slow) || (std::isnan(fast) && std::isnan(slow))) << "trial " << trial << ": " << fast << " against " << slow;
    // Every point's unwrapped angle from the offsets, against unwrapAngles.
    std::vector<double> a(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = std::atan2(y[i] - cy, x[i] - cx);
    const std::vector<double> u = unwrapAngles(a), offsets = unwrapOffsetsAbout(x, y, cx, cy);
    ASSERT_EQ(offsets.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const double angle = i == 0 ? a[0] : a[i] + offsets[i];
      EXPECT_TRUE(sameBits(angle, u[i]) || (std::isnan(angle) && std::isnan(u[i]))) << "trial " << trial << " point " << i;
    }
  }
  const std::vector<double> xs = {1.0, -0.0, -1.0}, ys = {0.0, 0.0, 1e-300};  // through the centre with dx = -0
  EXPECT_TRUE(sameBits(sweptAngleAbout(xs, ys, 0.0, 0.0), plain(xs, ys, 0.0, 0.0)));
  EXPECT_EQ(sweptAngleAbout({}, {}, 0.0, 0.0), 0.0);
}

// localSlope runs its whole windows side by side, in registers as wide as
// the CPU has, long ones from a transposed copy in overlapping stretches
// (issue 32); each slope must keep the bits of the plain one-window-at-a-
// time definition, ends, groups' remainders and overlaps included.
TEST(Filters, LocalSlopeHasTheBitsOfOneWindowAtATime) {
  auto plain = [](const std::vector<double>& v, double dt, std::size_t halfWidth) {
    const std::size_t n = v.size();
    std::vector<double> out(n, 0.0);
    halfWidth = std::max<std::size_t>(halfWidth, 1);
    for (std::size_t i = 0; i < n && n >= 2; ++i) {
      const std::size_t h = std::min({halfWidth, i, n - 1 - i});
      if (h == 0) {
        out[i] = i == 0 ? (v[1] - v[0]) / dt : (v[n - 1] - v[n - 2]) / dt;
        continue;
      }
      double num = 0.0, den = 0.0;
      for (std::size_t k = 1; k <= h; ++k) {
        num += static_cast<double>(k) * (v[i + k] - v[i - k]);
        den += 2.0 * static_cast<double>(k) * static_cast<double>(k);
      }
      out[i] = num / (den * dt);
    }
    return out;
  };
  std::mt19937 rng(32);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const std::size_t n : {2u, 3u, 7u, 47u, 48u, 100u, 333u, 1001u, 6001u}) {
    std::vector<double> v(n);
    double walk = 0.0;
    for (double& x : v) x = walk += normal(rng);
    for (const std::size_t halfWidth : {0u, 1u, 3u, 7u, 8u, 50u, 150u, 600u}) {
      const std::vector<double> fast = localSlope(v, 0.01, halfWidth), slow = plain(v, 0.01, halfWidth);
      ASSERT_EQ(fast.size(), slow.size());
      EXPECT_EQ(std::memcmp(fast.data(), slow.data(), sizeof(double) * n), 0) << "n " << n << " half width " << halfWidth;
    }
  }
}

TEST(Filters, UnwrapUndoesWrappingIntoMinusPiPi) {
  std::vector<double> wrapped, truth;
  for (int i = 0; i < 400; ++i) {
    truth.push_back(-0.05 * i);
    wrapped.push_back(std::remainder(truth.back(), 2.0 * std::numbers::pi));
  }
  const std::vector<double> u = unwrapAngles(wrapped);
  for (std::size_t i = 0; i < u.size(); ++i) EXPECT_NEAR(u[i], truth[i], 1e-9);
}

TEST(Filters, HalfWidthForADuration) {
  EXPECT_EQ(halfWidthFor(0.05, 0.01), 3u);  // 2.5 rounds away from zero: 7 samples, 0.06 s
  EXPECT_EQ(halfWidthFor(0.0, 0.01), 0u);
  EXPECT_EQ(halfWidthFor(1.0, 0.0), 0u);
}

}  // namespace
}  // namespace hemiroll::analysis
