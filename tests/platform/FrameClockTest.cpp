#include "engine/platform/FrameClock.h"

#include <gtest/gtest.h>

#include <vector>

namespace hemiroll::platform {
namespace {

// A fake clock: each call returns the next of the given times [s].
FrameClock::TimeSource times(std::vector<double> t) {
  auto index = std::make_shared<std::size_t>(0);
  return [t = std::move(t), index] { return t[std::min((*index)++, t.size() - 1)]; };
}

TEST(FrameClockTest, FirstTickIsZeroThenTheStepSinceTheLast) {
  FrameClock clock({}, times({10.0, 10.016, 10.05}));
  EXPECT_EQ(clock.tick(), 0.0);
  EXPECT_NEAR(clock.tick(), 0.016, 1e-12);  // exact up to the subtraction's rounding
  EXPECT_NEAR(clock.tick(), 0.034, 1e-12);
  EXPECT_EQ(clock.frames(), 3u);
}

TEST(FrameClockTest, LongStepsAreClampedAndBackwardsTimeGivesZero) {
  FrameClock clock({.maxStep = 0.1}, times({0.0, 5.0, 4.0}));
  clock.tick();
  EXPECT_EQ(clock.tick(), 0.1);
  EXPECT_EQ(clock.tick(), 0.0);
}

TEST(FrameClockTest, MedianFpsIgnoresASingleHitch) {
  std::vector<double> t;
  double now = 0.0;
  for (int i = 0; i < 30; ++i) {
    t.push_back(now);
    now += (i == 10) ? 0.5 : 1.0 / 60.0;  // one half-second hitch among 60 Hz frames
  }
  FrameClock clock({}, times(t));
  EXPECT_EQ(clock.medianFps(), 0.0);
  for (std::size_t i = 0; i < t.size(); ++i) clock.tick();
  EXPECT_NEAR(clock.medianFps(), 60.0, 1e-6);  // the median step is exactly 1/60 s up to rounding
}

TEST(FrameClockTest, MedianUsesOnlyTheLastWindowOfFrames) {
  std::vector<double> t;
  double now = 0.0;
  // Slow frames first (10 fps), then more than a window of fast ones (100 fps).
  for (int i = 0; i < 20; ++i) t.push_back(now), now += 0.1;
  for (std::size_t i = 0; i < FrameClock::kWindow + 5; ++i) t.push_back(now), now += 0.01;
  FrameClock clock({}, times(t));
  for (std::size_t i = 0; i < t.size(); ++i) clock.tick();
  EXPECT_NEAR(clock.medianFps(), 100.0, 1e-6);
}

}  // namespace
}  // namespace hemiroll::platform
