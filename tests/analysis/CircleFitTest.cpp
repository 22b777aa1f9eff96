// engine/analysis CircleFit: Taubin's fit, curvature finite for a line.

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace hemiroll::analysis
