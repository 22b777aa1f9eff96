#include "engine/haptics/TimingHistogram.h"

#include <gtest/gtest.h>

#include <memory>

namespace hemiroll::haptics {
namespace {

TEST(TimingHistogramTest, QuantilesAreBinUpperEdgesAndMaxIsExact) {
  auto h = std::make_unique<TimingHistogram>();
  EXPECT_EQ(h->quantile(0.5), 0.0);
  for (int i = 0; i < 1000; ++i) h->record(static_cast<std::int64_t>(i) * 1000 + 500);  // 0.5 .. 999.5 us
  EXPECT_EQ(h->count(), 1000u);
  EXPECT_DOUBLE_EQ(h->quantile(0.5), 500e-6);   // the 500th value lies in bin [499, 500) us
  EXPECT_DOUBLE_EQ(h->quantile(0.99), 990e-6);
  EXPECT_DOUBLE_EQ(h->max(), 999.5e-6);
  EXPECT_DOUBLE_EQ(h->quantile(1.0), 999.5e-6);  // capped by the exact maximum
  h->record(20'000'000);                          // 20 ms: the overflow bin
  EXPECT_DOUBLE_EQ(h->max(), 0.02);
  EXPECT_DOUBLE_EQ(h->quantile(1.0), 0.02);
  h->record(-5);  // a clock that went "backwards" counts as on time
  EXPECT_EQ(h->count(), 1002u);
  h->clear();
  EXPECT_EQ(h->count(), 0u);
}

}  // namespace
}  // namespace hemiroll::haptics
