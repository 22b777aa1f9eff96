// game/research/analysis FeaturesJson and FeatureTable: SI keys, "found" with a
// reason instead of numbers, one table row per trial.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "game/research/analysis/FeatureTable.h"
#include "game/research/analysis/FeaturesJson.h"
#include "tests/analysis/support/Synthetic.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

AnalysedTrial roseTrial(bool still) {
  AnalysedTrial t;
  t.data.id = "rose \"1\"";
  t.data.source = "somewhere/rose.csv";
  t.data.kind = "sim";
  const test::Planar rose = test::rose(0.015, 0.008, 8, -M_PI / 10, 30.0, 100.0);
  t.data.time = rose.t;
  t.data.massX = still ? std::vector<double>(rose.t.size(), 0.0) : rose.x;
  t.data.massY = still ? std::vector<double>(rose.t.size(), 0.0) : rose.y;
  t.data.contactX = t.data.massX;
  t.data.contactY = t.data.massY;
  for (double time : rose.t) t.data.psi.push_back(still ? 0.0 : -0.2 * time);
  t.features = analysis::analyzeTrial(t.data.samples());
  return t;
}

TEST(FeaturesJson, FoundFeaturesCarryNumbersWithUnitKeys) {
  const AnalysedTrial t = roseTrial(false);
  const nlohmann::json j = nlohmann::json::parse(featuresJson(t.data, t.features));
  EXPECT_EQ(j["trial"], "rose \"1\"");
  EXPECT_EQ(j["rose"]["found"], true);
  EXPECT_EQ(j["rose"]["leaves"], 9);
  EXPECT_NEAR(j["rose"]["leaf_radius_m"].get<double>(), 0.008, 0.0001);
  EXPECT_NEAR(j["phases"]["steady_rate_rad_per_s"].get<double>(), -0.2, 1e-6);
  EXPECT_EQ(j["rose"]["sense"], "clockwise");
  EXPECT_TRUE(j["helix"]["arc"].contains("curvature_per_m"));
}

TEST(FeaturesJson, MissingFeaturesCarryTheirReasonNotZeros) {
  const AnalysedTrial t = roseTrial(true);
  const std::string text = featuresJson(t.data, t.features);
  EXPECT_THAT(text, ::testing::Not(HasSubstr("nan")));
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["phases"]["found"], false);
  EXPECT_THAT(j["phases"]["reason"].get<std::string>(), HasSubstr("no steady precession"));
  EXPECT_EQ(j["rose"]["found"], false);
  EXPECT_FALSE(j["rose"].contains("leaf_radius_m"));
  EXPECT_THAT(j["rose"]["reason"].get<std::string>(), HasSubstr("does not move"));
  EXPECT_THAT(j["rose"]["note"].get<std::string>(), HasSubstr("whole trial"));
}

TEST(FeatureTable, OneRowPerTrialEmptyWhereNotFound) {
  const std::vector<AnalysedTrial> trials{roseTrial(false), roseTrial(true)};
  const std::string csv = featureTableCsv(trials);
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < csv.size();) {
    const std::size_t end = csv.find('\n', at);
    lines.push_back(csv.substr(at, end - at));
    at = end + 1;
  }
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_THAT(lines[0], HasSubstr("leaf_radius_m,leaf_radius_spread_m,outer_radius_m"));
  EXPECT_THAT(lines[1], HasSubstr("\"rose \"\"1\"\"\""));  // RFC 4180 quoting
  EXPECT_THAT(lines[1], HasSubstr(",9,"));
  EXPECT_THAT(lines[2], HasSubstr(",,"));  // the still trial's features are empty
  const std::string md = featureTableMarkdown(trials);
  EXPECT_THAT(md, HasSubstr("| 9 | 0.80 ± 0.00 | 2.30 ± 0.00 |"));
  EXPECT_THAT(md, HasSubstr("no rose: the point does not move"));
}

}  // namespace
}  // namespace hemiroll::game
