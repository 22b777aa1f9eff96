// engine/analysis Extrema: alternating extrema with hysteresis.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "engine/analysis/Extrema.h"

namespace hemiroll::analysis {
namespace {

TEST(Extrema, CosineExtremaAtTheirTimesAndValues) {
  // cos with period 100 samples: maxima at 100 n, minima at 50 + 100 n.
  // Sampled at 0.3 samples off the extremum, the parabola recovers it to
  // O(h^4): well within 1e-3 samples and 1e-5 in value.
  std::vector<double> v;
  for (int i = 0; i < 520; ++i) v.push_back(std::cos(2.0 * std::numbers::pi * (i + 0.3) / 100.0));
  const std::vector<Extremum> e = findExtrema(v, 0.5);
  ASSERT_EQ(e.size(), 10u);  // min at 49.7, max at 99.7, ..., max at 499.7 (the start is no extremum)
  EXPECT_FALSE(e.front().isMaximum);
  for (std::size_t i = 0; i < e.size(); ++i) {
    EXPECT_NEAR(e[i].position, 49.7 + 50.0 * static_cast<double>(i), 1e-3);
    EXPECT_NEAR(e[i].value, e[i].isMaximum ? 1.0 : -1.0, 1e-5);
    if (i > 0) {
      EXPECT_NE(e[i].isMaximum, e[i - 1].isMaximum);
    }
  }
}

TEST(Extrema, NoiseBelowTheHysteresisSplitsNothing) {
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  std::vector<double> v;
  for (int i = 0; i < 400; ++i) v.push_back(std::sin(2.0 * std::numbers::pi * i / 100.0) + noise(random));
  // Noise spans at most 0.2 < 0.5: exactly the 8 true extrema (peaks at 25, 125, ... troughs at 75, ...; the last trough at 375).
  EXPECT_EQ(findExtrema(v, 0.5).size(), 8u);
}

TEST(Extrema, FlatOrShortInputHasNone) {
  EXPECT_TRUE(findExtrema(std::vector<double>(50, 1.0), 0.1).empty());
  EXPECT_TRUE(findExtrema(std::vector<double>{1.0, 2.0}, 0.1).empty());
}

}  // namespace
}  // namespace hemiroll::analysis
