// engine/autopilot/LandingSearch and the landing shape it searches
// (HelixPolicy.h's LandingShape).

#include "engine/autopilot/LandingSearch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/autopilot/HelixPolicy.h"

namespace hemiroll::autopilot {
namespace {

// A bowl in the 16 knot coordinates with its floor at 1 mm on every one:
// success within 0.2 mm of it (the spread starts at 2 mm).
ShapeScore bowl(const LandingShape& s) {
  double cost = 0.0, worst = 0.0;
  for (const physics::Vec2& k : s.knots)
    for (int c = 0; c < 2; ++c) {
      const double d = k[c] - 0.001;
      cost += d * d;
      worst = std::max(worst, std::abs(d));
    }
  return ShapeScore{worst < 2e-4, cost};
}

TEST(LandingSearch, FindsAShapeNearAnOptimumAndRepeatsItsDrawsPerSeed) {
  const ScoreShape score = bowl;
  LandingSearchDef def;
  def.rounds = 40;
  def.seed = 3;
  const std::optional<LandingShape> a = searchLandingShape(def, score);
  ASSERT_TRUE(a.has_value());
  EXPECT_NEAR(a->knots[0].x(), 0.001, 2e-4);
  const std::optional<LandingShape> b = searchLandingShape(def, score);
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(a->knots, b->knots);  // same seed, same draws
  def.rounds = 1;
  EXPECT_FALSE(searchLandingShape(def, score).has_value());  // one round from zero cannot get there
}

TEST(LandingSearch, OutOfTimeEndsTheSearchBeforeTheNextShape) {
  // The same bowl, solvable in 40 rounds; the clock runs out after five
  // shapes: a sixth is never scored, and nothing is returned.
  int scored = 0, asked = 0;
  const auto score = [&](const LandingShape& s) {
    ++scored;
    double cost = 0.0;
    for (const physics::Vec2& k : s.knots) cost += (k - physics::Vec2(0.001, 0.001)).squaredNorm();
    return ShapeScore{cost < 1e-12, cost};
  };
  LandingSearchDef def;
  def.rounds = 40;
  def.outOfTime = [&] { return ++asked > 5; };
  EXPECT_FALSE(searchLandingShape(def, score).has_value());
  EXPECT_EQ(scored, 5);
  EXPECT_EQ(asked, 6);
}

TEST(LandingSearch, ScoringInBatchesFindsTheSameShapeAndAsksTheClockPerBatch) {
  // The bowl, scored a batch at a time: the shape found is the
  // one-at-a-time search's, bit for bit, for any batch size (the draws and
  // the order of judging do not change); the clock is asked before each
  // batch.
  const ScoreShape one = bowl;
  LandingSearchDef def;
  def.rounds = 40;
  def.seed = 3;
  const std::optional<LandingShape> alone = searchLandingShape(def, one);
  ASSERT_TRUE(alone.has_value());
  for (int batch : {2, 5, 8, 32}) {
    def.batch = batch;
    std::size_t largest = 0;
    const std::optional<LandingShape> batched = searchLandingShape(def, [&](const std::vector<LandingShape>& shapes) {
      largest = std::max(largest, shapes.size());
      std::vector<ShapeScore> scores;
      for (const LandingShape& s : shapes) scores.push_back(one(s));
      return scores;
    });
    ASSERT_TRUE(batched.has_value()) << "batch " << batch;
    EXPECT_EQ(batched->knots, alone->knots) << "batch " << batch;
    EXPECT_EQ(largest, static_cast<std::size_t>(batch));
  }
  int asked = 0;
  std::size_t scored = 0;
  def.batch = 8;
  def.outOfTime = [&] { return ++asked > 2; };
  EXPECT_FALSE(searchLandingShape(def, [&](const std::vector<LandingShape>& shapes) {
                 scored += shapes.size();
                 return std::vector<ShapeScore>(shapes.size());
               }).has_value());
  EXPECT_EQ(scored, 16u);  // two batches of 8, then the clock ran out
  EXPECT_EQ(asked, 3);
}

TEST(LandingShape, ADefaultShapeIsNoOffsetAtAll) {
  // Eigen vectors are not zeroed by value-initialisation; a plain landing
  // (no shape) must add nothing. Built in memory filled with garbage first,
  // so that a shape that forgot to set its knots shows it.
  alignas(LandingShape) unsigned char memory[sizeof(LandingShape)];
  std::memset(memory, 0x5a, sizeof memory);
  const LandingShape* s = new (memory) LandingShape;  // default-initialised, as `= {}` and members are
  for (double t = 0.0; t < LandingShape::kKnots * s->spacing; t += 0.05) EXPECT_EQ(s->at(t), physics::Vec2::Zero()) << t;
  s->~LandingShape();
}

TEST(LandingShape, IsLinearBetweenKnotsAndZeroAfterTheLast) {
  LandingShape s;
  s.knots[0] = physics::Vec2(0.002, 0.0);
  s.knots[1] = physics::Vec2(0.0, 0.004);
  EXPECT_NEAR(s.at(0.2).x(), 0.001, 1e-15);  // halfway from knot 0 to knot 1 (0.4 s apart)
  EXPECT_NEAR(s.at(0.2).y(), 0.002, 1e-15);
  EXPECT_EQ(s.at(-0.1), physics::Vec2::Zero());
  EXPECT_EQ(s.at(LandingShape::kKnots * s.spacing + 0.1), physics::Vec2::Zero());
}

}  // namespace
}  // namespace hemiroll::autopilot
