#include "engine/platform/FramePacer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hemiroll::platform {
namespace {

// A fake clock that only the pacer's sleep and the test's "work" move.
struct FakeTime {
  double now = 100.0;
  std::vector<double> sleeps;
  FramePacer pacer() {
    return FramePacer({.now = [this] { return now; },
                       .sleep = [this](double s) {
                         sleeps.push_back(s);
                         now += s;
                       }});
  }
};

TEST(FramePacerTest, AShortFrameSleepsToItsDeadline) {
  FakeTime t;
  FramePacer p = t.pacer();
  p.pace(60.0);  // the first frame only sets the beat
  EXPECT_TRUE(t.sleeps.empty());
  for (int i = 0; i < 10; ++i) {
    t.now += 0.004;  // 4 ms of work
    p.pace(60.0);
  }
  ASSERT_EQ(t.sleeps.size(), 10u);
  for (const double s : t.sleeps) EXPECT_NEAR(s, 1.0 / 60.0 - 0.004, 1e-9);
  // Ten frames took ten intervals: 60 fps, not the ~250 the work alone allows.
  EXPECT_NEAR(t.now - 100.0, 10.0 / 60.0, 1e-9);
  EXPECT_NEAR(p.totalSleep(), 10 * (1.0 / 60.0 - 0.004), 1e-9);
}

TEST(FramePacerTest, ALateFrameIsNotMadeUpByABurst) {
  FakeTime t;
  FramePacer p = t.pacer();
  p.pace(60.0);
  t.now += 0.1;  // a 100 ms hitch
  p.pace(60.0);
  EXPECT_EQ(p.lastSleep(), 0.0);
  t.now += 0.004;
  p.pace(60.0);
  // The next frame still gets its whole interval from the late one's end.
  EXPECT_NEAR(p.lastSleep(), 1.0 / 60.0 - 0.004, 1e-9);
}

TEST(FramePacerTest, AFrameThatEndsOnTheDisplaysBeatSleepsNothing) {
  // Vsync paced the swap to 60 Hz already: the cap of 60 must not add a sleep.
  FakeTime t;
  FramePacer p = t.pacer();
  p.pace(60.0);
  for (int i = 0; i < 5; ++i) {
    t.now += 1.0 / 60.0;
    p.pace(60.0);
  }
  EXPECT_TRUE(t.sleeps.empty() || t.sleeps.back() < 1e-9);
}

TEST(FramePacerTest, ALowerRateSleepsLongerAndNoRateDoesNotPace) {
  FakeTime t;
  FramePacer p = t.pacer();
  p.pace(15.0);
  t.now += 0.004;
  p.pace(15.0);
  EXPECT_NEAR(p.lastSleep(), 1.0 / 15.0 - 0.004, 1e-9);
  for (const double off : {0.0, -1.0, std::nan("")}) {
    t.now += 0.004;
    p.pace(off);
    EXPECT_EQ(p.lastSleep(), 0.0) << off;
  }
}

}  // namespace
}  // namespace hemiroll::platform
