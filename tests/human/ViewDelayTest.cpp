// engine/human/ViewDelay: a view comes back exactly `delay` later, never sooner.

#include "engine/human/ViewDelay.h"

#include <gtest/gtest.h>

namespace hemiroll::human {
namespace {

TEST(ViewDelay, NothingIsSeenUntilTheDelayHasPassedThenEachViewExactlyThatLate) {
  const double tick = 0.001, delay = 0.2;
  ViewDelay d(delay, tick);
  EXPECT_EQ(d.lagTicks(), 200u);
  for (int i = 0; i < 1000; ++i) {
    ScreenView v;
    v.time = i * tick;
    const ScreenView* seen = d.push(v);
    if (i < 200) {
      EXPECT_EQ(seen, nullptr) << "tick " << i;
    } else {
      ASSERT_NE(seen, nullptr) << "tick " << i;
      EXPECT_NEAR(v.time - seen->time, delay, 1e-12) << "tick " << i;
    }
  }
}

TEST(ViewDelay, ALongerDelaySeesOlderViews) {
  ViewDelay shortDelay(0.2, 0.001), longDelay(0.35, 0.001);
  const ScreenView *a = nullptr, *b = nullptr;
  for (int i = 0; i < 500; ++i) {
    ScreenView v;
    v.time = i * 0.001;
    a = shortDelay.push(v);
    b = longDelay.push(v);
  }
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_NEAR(a->time - b->time, 0.15, 1e-12);
}

}  // namespace
}  // namespace hemiroll::human
