// engine/analysis Extrema: alternating extrema with hysteresis.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
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

// findExtrema holds the extremes so far as values, not only as indices
// (issue 32): its extrema must be the indexed loop's (this is it, with the
// same refinement), to the bit, on random walks with plateaus, ties, NaNs
// and a NaN first sample.
TEST(Extrema, HoldsTheIndexedLoopsExtrema) {
  auto plain = [](const std::vector<double>& values, double delta) {
    std::vector<Extremum> out;
    auto refined = [&](std::size_t i, bool isMaximum) {
      Extremum e{static_cast<double>(i), values[i], isMaximum};
      if (i == 0 || i + 1 >= values.size()) return e;
      const double a = values[i - 1], b = values[i], c = values[i + 1];
      const double den = a - 2.0 * b + c;
      if (den == 0.0) return e;
      const double shift = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
      e.position += shift;
      e.value = b - 0.25 * (a - c) * shift;
      return e;
    };
    auto swungInto = [&](std::size_t at, bool isMaximum) {
      for (std::size_t i = 0; i < at; ++i)
        if (isMaximum ? values[i] <= values[at] - delta : values[i] >= values[at] + delta) return true;
      return false;
    };
    if (values.size() < 3 || !(delta > 0.0)) return out;
    std::size_t maxAt = 0, minAt = 0;
    int looking = 0;
    for (std::size_t i = 1; i < values.size(); ++i) {
      if (values[i] > values[maxAt]) maxAt = i;
      if (values[i] < values[minAt]) minAt = i;
      if (looking >= 0 && values[i] < values[maxAt] - delta) {
        if (looking > 0 || swungInto(maxAt, true)) out.push_back(refined(maxAt, true));
        looking = -1;
        minAt = i;
      } else if (looking <= 0 && values[i] > values[minAt] + delta) {
        if (looking < 0 || swungInto(minAt, false)) out.push_back(refined(minAt, false));
        looking = 1;
        maxAt = i;
      }
    }
    return out;
  };
  auto sameBits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  std::mt19937_64 random(38);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 49);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<double> v(3 + static_cast<std::size_t>(trial) * 11);
    double walk = 0.0;
    for (double& x : v) {
      const int p = pick(random);
      walk += p < 5 ? 0.0 : normal(random);                        // plateaus and ties
      x = p == 5 && trial % 3 == 0 ? std::nan("") : std::round(4.0 * walk) / 4.0;
    }
    if (trial % 10 == 1) v[0] = std::nan("");
    for (const double delta : {0.25, 1.0, 3.0}) {
      const std::vector<Extremum> fast = findExtrema(v, delta), slow = plain(v, delta);
      ASSERT_EQ(fast.size(), slow.size()) << "trial " << trial << " delta " << delta;
      for (std::size_t i = 0; i < fast.size(); ++i) {
        EXPECT_TRUE(sameBits(fast[i].position, slow[i].position)) << "trial " << trial << " extremum " << i;
        EXPECT_TRUE(sameBits(fast[i].value, slow[i].value) || (std::isnan(fast[i].value) && std::isnan(slow[i].value)))
            << "trial " << trial << " extremum " << i;
        EXPECT_EQ(fast[i].isMaximum, slow[i].isMaximum) << "trial " << trial << " extremum " << i;
      }
    }
  }
}

}  // namespace
}  // namespace hemiroll::analysis
