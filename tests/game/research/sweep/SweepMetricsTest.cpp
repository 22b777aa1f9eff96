// game/research/sweep/SweepMetrics: every map metric is a sweep column (or
// "stopped"), and the aggregates over a cell's points.

#include "game/research/sweep/SweepMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string_view>

#include "game/research/sweep/SweepTable.h"

namespace hemiroll::game {
namespace {

TEST(SweepMetrics, EveryMetricIsAColumnOrStopped) {
  for (const SweepMetric& m : sweepMetrics()) {
    if (std::string_view(m.name) != "stopped") {
      EXPECT_NO_THROW(sweepColumn(m.name)) << m.name;
    }
    EXPECT_EQ(findSweepMetric(m.name), &m);
  }
  EXPECT_EQ(findSweepMetric("nope"), nullptr);
}

TEST(SweepMetrics, Aggregates) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> v = {3.0, nan, 1.0, 2.0, 10.0};
  const SweepMetric& share = *findSweepMetric("steady_fraction");              // larger is better
  const SweepMetric& spread = *findSweepMetric("steady_rate_relative_spread");  // smaller is better
  const SweepMetric& rate = *findSweepMetric("steady_rate_rad_per_s");          // neither
  EXPECT_EQ(aggregateValues(v, Aggregate::Median, share), 2.5);  // NaN left out
  EXPECT_EQ(aggregateValues(v, Aggregate::Mean, share), 4.0);
  EXPECT_EQ(aggregateValues(v, Aggregate::Min, share), 1.0);
  EXPECT_EQ(aggregateValues(v, Aggregate::Max, share), 10.0);
  EXPECT_EQ(aggregateValues(v, Aggregate::Best, share), 10.0);
  EXPECT_EQ(aggregateValues(v, Aggregate::Best, spread), 1.0);
  EXPECT_EQ(aggregateValues(v, Aggregate::Best, rate), 2.5);
  EXPECT_TRUE(std::isnan(aggregateValues({nan}, Aggregate::Mean, share)));
  EXPECT_TRUE(std::isnan(aggregateValues({}, Aggregate::Median, share)));
  for (const char* name : {"median", "mean", "min", "max", "best"}) {
    ASSERT_TRUE(parseAggregate(name));
    EXPECT_STREQ(aggregateName(*parseAggregate(name)), name);
  }
  EXPECT_FALSE(parseAggregate("average"));
}

}  // namespace
}  // namespace hemiroll::game
