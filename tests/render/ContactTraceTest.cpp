#include "engine/render/ContactTrace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hemiroll::render {
namespace {

TEST(ContactTraceTest, KeepsTheNewestPointsUpToCapacity) {
  ContactTrace trace({.capacity = 4, .minSpacing = 0.0, .fadeTime = 10.0});
  const TracePoint* storage = &trace.at(0);
  for (int i = 0; i < 10; ++i) trace.push(0.01 * i, 0.0, i);
  EXPECT_EQ(trace.size(), 4u);
  EXPECT_EQ(trace.capacity(), 4u);
  // Oldest first: points 6, 7, 8, 9.
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(trace.at(i).time, 6.0 + i);
  // Bounded memory: the ring is the same storage it was at construction.
  bool inside = false;
  for (std::size_t i = 0; i < 4; ++i) inside = inside || &trace.at(0) == storage + i;
  EXPECT_TRUE(inside);
}

TEST(ContactTraceTest, SkipsPointsCloserThanTheSpacingAndNonFinitePoints) {
  ContactTrace trace({.capacity = 16, .minSpacing = 1e-3, .fadeTime = 10.0});
  trace.push(0.0, 0.0, 0.0);
  trace.push(0.0005, 0.0, 0.1);  // 0.5 mm: below the 1 mm spacing
  trace.push(0.002, 0.0, 0.2);
  trace.push(std::nan(""), 0.0, 0.3);
  trace.push(0.0, std::numeric_limits<double>::infinity(), 0.4);
  trace.push(0.004, 0.0, std::nan(""));
  ASSERT_EQ(trace.size(), 2u);
  EXPECT_EQ(trace.at(1).x, 0.002);
  trace.clear();
  EXPECT_EQ(trace.size(), 0u);
}

TEST(ContactTraceTest, AlphaFadesLinearlyToAFloor) {
  ContactTrace trace({.capacity = 4, .minSpacing = 0.0, .fadeTime = 20.0});
  EXPECT_EQ(trace.alphaForAge(0.0), 1.0);
  EXPECT_DOUBLE_EQ(trace.alphaForAge(5.0), 0.75);
  EXPECT_EQ(trace.alphaForAge(100.0), ContactTrace::kMinAlpha);
  EXPECT_EQ(trace.alphaForAge(-1.0), 1.0);  // a point "from the future" (clock reset) is drawn fully
}

TEST(ContactTraceTest, RejectsAUselessDefinition) {
  EXPECT_THROW(ContactTrace({.capacity = 1}), std::invalid_argument);
  EXPECT_THROW(ContactTrace({.capacity = 8, .minSpacing = -1.0}), std::invalid_argument);
  EXPECT_THROW(ContactTrace({.capacity = 8, .minSpacing = 0.0, .fadeTime = 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace hemiroll::render
