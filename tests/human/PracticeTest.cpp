// engine/human/Practice: the law of practice on the motor noise - the
// novice's on the first trial, then down as a power of the trials
// practised, never below the floor.

#include "engine/human/Practice.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hemiroll::human {
namespace {

TEST(PracticeTest, TheFirstTrialHasTheNovicesNoiseAndPracticeTakesItTowardsTheFloor) {
  const PracticeDef def;  // novice 0.2, exponent 0.4
  EXPECT_DOUBLE_EQ(practisedNoise(def, 0.1, 0), 0.2);
  // The law written out: floor + (novice - floor) (N + 1)^-exponent.
  EXPECT_NEAR(practisedNoise(def, 0.1, 1), 0.1 + 0.1 / std::pow(2.0, 0.4), 1e-15);
  EXPECT_NEAR(practisedNoise(def, 0.1, 9), 0.1 + 0.1 / std::pow(10.0, 0.4), 1e-15);
  double last = 1.0;
  for (int n = 0; n < 200; ++n) {
    const double noise = practisedNoise(def, 0.1, n);
    EXPECT_LT(noise, last) << n;  // every trial practised helps, less and less
    EXPECT_GT(noise, 0.1) << n;
    last = noise;
  }
  // The power law's slow tail: after 1000 trials still above the floor by
  // (1001)^-0.4 of the novice's excess, about 6 %.
  EXPECT_NEAR((practisedNoise(def, 0.1, 1000) - 0.1) / 0.1, std::pow(1001.0, -0.4), 1e-12);
}

TEST(PracticeTest, ANoviceNoNoisierThanTheFloorLearnsNothing) {
  PracticeDef def;
  def.noviceNoise = 0.05;
  EXPECT_EQ(practisedNoise(def, 0.1, 0), 0.1);
  EXPECT_EQ(practisedNoise(def, 0.1, 50), 0.1);
}

}  // namespace
}  // namespace hemiroll::human
