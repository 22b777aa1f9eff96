// engine/analysis CircleFit: Taubin's fit, curvature finite for a line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "engine/analysis/CircleFit.h"

namespace hemiroll::analysis {
namespace {

TEST(CircleFit, ExactArcGivesItsCircle) {
  std::vector<double> x, y;
  for (int i = 0; i <= 100; ++i) {
    const double a = 0.3 + 1.2 * i / 100.0;  // a 69 degree arc
    x.push_back(0.02 + 0.05 * std::cos(a));
    y.push_back(-0.01 + 0.05 * std::sin(a));
  }
  const CircleFit fit = fitCircle(x, y);
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR(fit.radius, 0.05, 1e-9);
  EXPECT_NEAR(fit.curvature, 20.0, 1e-6);
  EXPECT_NEAR(fit.centreX, 0.02, 1e-9);
  EXPECT_NEAR(fit.centreY, -0.01, 1e-9);
  EXPECT_LT(fit.rmsResidual, 1e-12);
}

TEST(CircleFit, NoisyArcWithinItsStandardError) {
  std::mt19937_64 random(3);
  std::normal_distribution<double> noise(0.0, 1e-4);
  std::vector<double> x, y;
  for (int i = 0; i <= 400; ++i) {
    const double a = 2.0 * i / 400.0;
    x.push_back(0.05 * std::cos(a) + noise(random));
    y.push_back(0.05 * std::sin(a) + noise(random));
  }
  const CircleFit fit = fitCircle(x, y);
  // Chord 0.084 m, 401 points: Gluckstern's sigma_k = 1e-4 / 0.084^2 * sqrt(720 / 405) = 0.019 1/m;
  // 0.1 1/m is five of them.
  EXPECT_NEAR(fit.curvature, 20.0, 0.1);
  EXPECT_NEAR(fit.rmsResidual, 1e-4, 1e-5);
}

TEST(CircleFit, StraightLineHasZeroCurvatureNotInfiniteRadius) {
  std::vector<double> x, y;
  for (int i = 0; i < 50; ++i) x.push_back(0.001 * i), y.push_back(0.5 * 0.001 * i + 0.3);
  const CircleFit fit = fitCircle(x, y);
  ASSERT_TRUE(fit.ok);
  EXPECT_LT(fit.curvature, 1e-6);
  EXPECT_LT(fit.rmsResidual, 1e-12);
  EXPECT_TRUE(std::isfinite(fit.radius));
}

TEST(CircleFit, TooFewOrCoincidentPointsAreNoFit) {
  EXPECT_FALSE(fitCircle(std::vector<double>{0.0, 1.0}, std::vector<double>{0.0, 1.0}).ok);
  EXPECT_FALSE(fitCircle(std::vector<double>(5, 0.1), std::vector<double>(5, 0.2)).ok);
}

// The fit as it was, one point at a time, X and Y worked out in each pass.
CircleFit plainFit(std::span<const double> x, std::span<const double> y) {
  CircleFit fit;
  const std::size_t n = std::min(x.size(), y.size());
  if (n < 3) return fit;
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) mx += x[i], my += y[i];
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) scale = std::max({scale, std::abs(x[i] - mx), std::abs(y[i] - my)});
  if (!(scale > 0.0) || !std::isfinite(scale)) return fit;
  double Mxx = 0, Myy = 0, Mxy = 0, Mxz = 0, Myz = 0, Mzz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double X = (x[i] - mx) / scale, Y = (y[i] - my) / scale, Z = X * X + Y * Y;
    Mxx += X * X, Myy += Y * Y, Mxy += X * Y, Mxz += X * Z, Myz += Y * Z, Mzz += Z * Z;
  }
  const double inv = 1.0 / static_cast<double>(n);
  Mxx *= inv, Myy *= inv, Mxy *= inv, Mxz *= inv, Myz *= inv, Mzz *= inv;
  const double Mz = Mxx + Myy;
  const double covXY = Mxx * Myy - Mxy * Mxy;
  const double minorVariance = 0.5 * (Mz - std::sqrt((Mxx - Myy) * (Mxx - Myy) + 4.0 * Mxy * Mxy));
  auto line = [&] {
    fit.ok = true;
    fit.rmsResidual = scale * std::sqrt(std::max(0.0, minorVariance));
    return fit;
  };
  if (minorVariance <= 1e-12 * Mz) return line();
  const double varZ = Mzz - Mz * Mz;
  const double A3 = 4.0 * Mz;
  const double A2 = -3.0 * Mz * Mz - Mzz;
  const double A1 = varZ * Mz + 4.0 * covXY * Mz - Mxz * Mxz - Myz * Myz;
  const double A0 = Mxz * (Mxz * Myy - Myz * Mxy) + Myz * (Myz * Mxx - Mxz * Mxy) - varZ * covXY;
  double root = 0.0, value = A0;
  for (int iter = 0; iter < 99; ++iter) {
    const double slope = A1 + root * (2.0 * A2 + 3.0 * A3 * root);
    if (slope == 0.0) break;
    const double next = root - value / slope;
    if (!std::isfinite(next)) break;
    const double nextValue = A0 + next * (A1 + next * (A2 + next * A3));
    if (std::abs(nextValue) >= std::abs(value) || std::abs(next - root) <= 1e-15 * std::abs(next)) {
      if (std::abs(nextValue) < std::abs(value)) root = next;
      break;
    }
    root = next, value = nextValue;
  }
  const double det = root * root - root * Mz + covXY;
  const double nx = Mxz * (Myy - root) - Myz * Mxy;
  const double ny = Myz * (Mxx - root) - Mxz * Mxy;
  const double S = std::sqrt(nx * nx + ny * ny + 4.0 * det * det * Mz);
  if (!(S > 0.0) || !std::isfinite(S)) return line();
  const double A = det / S, B = -nx / S, C = -ny / S, D = -Mz * det / S;
  fit.ok = true;
  fit.curvature = 2.0 * std::abs(A) / scale;
  if (fit.curvature > 0.0) {
    fit.radius = 1.0 / fit.curvature;
    fit.centreX = mx + scale * nx / (2.0 * det);
    fit.centreY = my + scale * ny / (2.0 * det);
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double X = (x[i] - mx) / scale, Y = (y[i] - my) / scale;
    const double P = A * (X * X + Y * Y) + B * X + C * Y + D;
    const double d = 2.0 * P / (1.0 + std::sqrt(std::max(0.0, 1.0 + 4.0 * A * P)));
    sum += d * d;
  }
  fit.rmsResidual = scale * std::sqrt(sum * inv);
  return fit;
}

// fitCircle works out the scaled coordinates once and takes the largest
// offset, the divisions and the roots two points at a time (issue 32): the
// fit must be the plain one's to the bit, on arcs, lines, scatter, odd and
// even counts, points with a NaN or an infinity among them.
TEST(CircleFit, HasThePlainFitsBits) {
  std::mt19937_64 random(37);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto sameBits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 3 + static_cast<std::size_t>(trial % 131) * 7 + trial % 2;
    const double radius = std::exp(3.0 * normal(random)), noise = trial % 3 == 0 ? 0.0 : std::exp(-6.0 + 2.0 * normal(random));
    const double arc = trial % 5 == 0 ? 0.0 : std::abs(normal(random)) * 2.0;  // 0: a straight line
    std::vector<double> x(n), y(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double a = arc * static_cast<double>(i) / static_cast<double>(n);
      x[i] = arc == 0.0 ? 0.01 * static_cast<double>(i) : radius * std::cos(a) + noise * normal(random);
      y[i] = arc == 0.0 ? 0.3 + 0.005 * static_cast<double>(i) : radius * std::sin(a) + noise * normal(random);
    }
    if (trial % 17 == 3) x[n / 2] = std::numeric_limits<double>::quiet_NaN();
    if (trial % 19 == 4) y[n - 1] = std::numeric_limits<double>::infinity();
    if (trial % 23 == 5) std::fill(x.begin(), x.end(), 0.25);  // on a vertical line, or one point
    if (trial % 4 == 1) {  // a whole circle and its centre, where 1 + 4 A P is 0 up to round-off
      for (std::size_t i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
        x[i] = radius * std::cos(a), y[i] = radius * std::sin(a);
      }
      x.insert(x.end(), 3, 0.0), y.insert(y.end(), 3, 0.0);
    }
    const CircleFit fast = fitCircle(x, y), slow = plainFit(x, y);
    EXPECT_EQ(fast.ok, slow.ok) << "trial " << trial;
    EXPECT_TRUE(sameBits(fast.curvature, slow.curvature)) << "trial " << trial;
    EXPECT_TRUE(sameBits(fast.centreX, slow.centreX)) << "trial " << trial;
    EXPECT_TRUE(sameBits(fast.centreY, slow.centreY)) << "trial " << trial;
    EXPECT_TRUE(sameBits(fast.radius, slow.radius)) << "trial " << trial;
    EXPECT_TRUE(sameBits(fast.rmsResidual, slow.rmsResidual)) << "trial " << trial << ": " << fast.rmsResidual << " against " << slow.rmsResidual;
  }
}

}  // namespace
}  // namespace hemiroll::analysis
