// game/research/analysis/LearningCurves: per participant and per group, by trial
// and by block, checked against the means and standard deviations worked
// out here by hand from a small made-up experiment; the CSV's long format;
// the plots are SVG documents with a series per group.

#include "game/research/analysis/LearningCurves.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/XmlCheck.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

ExperimentTrial trial(const std::string& participant, const std::string& group, int order, int index,
                      const std::string& block, int place, double time, bool success) {
  ExperimentTrial t;
  t.participant = participant;
  t.group = group;
  t.blockOrder = order;
  t.trialIndex = index;
  t.blockName = block;
  t.block = place;
  t.measures["time_s"] = time;
  t.measures["success"] = success ? 1.0 : 0.0;
  return t;
}

// Two groups; a and b in group g (b with the two last blocks swapped), c in h.
std::vector<ExperimentTrial> experiment() {
  return {trial("a", "g", 1, 1, "train", 1, 10.0, false), trial("a", "g", 1, 2, "train", 1, 8.0, true),
          trial("a", "g", 1, 3, "test", 2, 6.0, true),    trial("a", "g", 1, 4, "transfer", 3, 9.0, false),
          trial("b", "g", 2, 1, "train", 1, 14.0, false), trial("b", "g", 2, 2, "train", 1, 10.0, false),
          trial("b", "g", 2, 3, "transfer", 2, 12.0, true), trial("b", "g", 2, 4, "test", 3, 7.0, true),
          trial("c", "h", 1, 1, "train", 1, 20.0, false), trial("c", "h", 1, 2, "train", 1, 18.0, true),
          trial("c", "h", 1, 3, "test", 2, 15.0, true),   trial("c", "h", 1, 4, "transfer", 3, 16.0, true)};
}

const CurvePoint* find(const std::vector<CurvePoint>& points, const std::string& scope, const std::string& who,
                       const std::string& by, double x, const std::string& measure) {
  for (const CurvePoint& p : points)
    if (p.scope == scope && (scope == "group" ? p.group : p.participant) == who && p.by == by && p.x == x &&
        p.measure == measure)
      return &p;
  return nullptr;
}

TEST(LearningCurvesTest, MeansAndSpreadsAreTheOnesWorkedOutByHand) {
  const std::vector<CurvePoint> points = learningCurves(experiment(), {"time_s", "success"});
  // Participant a by trial: its own values, n 1, no spread.
  const CurvePoint* a3 = find(points, "participant", "a", "trial", 3, "time_s");
  ASSERT_NE(a3, nullptr);
  EXPECT_EQ(a3->n, 1);
  EXPECT_EQ(a3->mean, 6.0);
  EXPECT_TRUE(std::isnan(a3->sd));
  // Participant b by block, "train" (rank 1): (14 + 10) / 2 = 12, sd sqrt(((2)^2 + (2)^2) / 1) = 2.828...
  const CurvePoint* bTrain = find(points, "participant", "b", "block", 1, "time_s");
  ASSERT_NE(bTrain, nullptr);
  EXPECT_EQ(bTrain->blockName, "train");
  EXPECT_EQ(bTrain->n, 2);
  EXPECT_DOUBLE_EQ(bTrain->mean, 12.0);
  EXPECT_DOUBLE_EQ(bTrain->sd, std::sqrt(8.0));
  // Group g by trial 1: a 10, b 14 -> mean 12, sd sqrt(8).
  const CurvePoint* g1 = find(points, "group", "g", "trial", 1, "time_s");
  ASSERT_NE(g1, nullptr);
  EXPECT_EQ(g1->n, 2);
  EXPECT_DOUBLE_EQ(g1->mean, 12.0);
  EXPECT_DOUBLE_EQ(g1->sd, std::sqrt(8.0));
  // Group g by block "test": ranked 2 (the order of block order 1), though b
  // played it third; a 6, b 7 -> 6.5, sd sqrt(0.5).
  const CurvePoint* gTest = find(points, "group", "g", "block", 2, "time_s");
  ASSERT_NE(gTest, nullptr);
  EXPECT_EQ(gTest->blockName, "test");
  EXPECT_DOUBLE_EQ(gTest->mean, 6.5);
  EXPECT_DOUBLE_EQ(gTest->sd, std::sqrt(0.5));
  // Group g's success by block "train": a's rate 0.5, b's 0 -> 0.25, sd sqrt(0.125).
  const CurvePoint* gTrainSuccess = find(points, "group", "g", "block", 1, "success");
  ASSERT_NE(gTrainSuccess, nullptr);
  EXPECT_DOUBLE_EQ(gTrainSuccess->mean, 0.25);
  EXPECT_DOUBLE_EQ(gTrainSuccess->sd, std::sqrt(0.125));
  // Group h has one participant: n 1, no spread.
  const CurvePoint* h4 = find(points, "group", "h", "trial", 4, "time_s");
  ASSERT_NE(h4, nullptr);
  EXPECT_EQ(h4->n, 1);
  EXPECT_EQ(h4->mean, 16.0);
  EXPECT_TRUE(std::isnan(h4->sd));
  // Every point: participants 3 x (4 trials + 3 blocks), groups (4 + 3) x 2; per measure.
  EXPECT_EQ(points.size(), 2u * (3u * 7u + 2u * 7u));
}

TEST(LearningCurvesTest, TheCsvIsLongFormatAndThePlotsAreSvg) {
  const std::vector<CurvePoint> points = learningCurves(experiment(), {"time_s"});
  const std::string csv = learningCurvesCsv(points);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "scope,participant,group,by,x,block_name,measure,n,mean,sd");
  EXPECT_THAT(csv, HasSubstr("\ngroup,,g,block,2,test,time_s,2,6.5,"));
  EXPECT_THAT(csv, HasSubstr("\nparticipant,a,g,trial,3,,time_s,1,6,\n"));
  const OutputFiles plots = learningCurvePlots(points, {"time_s"});
  ASSERT_EQ(plots.size(), 3u);
  EXPECT_EQ(plots[0].first, "curves_time_s_by_trial.svg");
  EXPECT_EQ(plots[1].first, "curves_time_s_by_block.svg");
  EXPECT_EQ(plots[2].first, "participants_time_s_by_trial.svg");
  for (const auto& [name, svg] : plots) {
    EXPECT_EQ(test::xmlProblem(svg), "") << name;
    EXPECT_THAT(svg, HasSubstr(">g<")) << name << ": the legend names the groups";
    EXPECT_THAT(svg, HasSubstr(">h<")) << name;
  }
}

}  // namespace
}  // namespace hemiroll::game
