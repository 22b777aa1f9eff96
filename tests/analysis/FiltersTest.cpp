// engine/analysis Filters: centred moving average, local slope, unwrapping.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
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
