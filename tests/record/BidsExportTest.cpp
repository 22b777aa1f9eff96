#include "engine/record/BidsExport.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "tests/record/support/RecordRows.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

std::vector<std::vector<std::string>> tsv(const std::filesystem::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(hemiroll::test::TempDirectory::read(path));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::istringstream l(line);
    for (std::string f; std::getline(l, f, '\t');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

Recording sample() {
  Recording r;
  r.meta.participant = "p-01";
  r.meta.session = "2";
  r.meta.trialId = "trial-007";
  r.meta.taskName = "hemiroll";
  r.meta.recordEvery = 10;
  r.meta.guidance.kind = haptics::GuidanceKind::Autopilot;
  r.meta.guidance.stiffness = 300.0;
  r.meta.guidance.scale = 0.75;
  r.rows = test::randomRows(30, 5);
  r.status.complete = true;
  return r;
}

TEST(BidsExportTest, FileNamesFollowTheBidsEntities) {
  Recording r = sample();
  EXPECT_EQ(BidsExport::stem(r), "sub-p01_ses-2_task-hemiroll_tracksys-hemiroll_run-7");
  r.meta.session.clear();
  r.meta.trialId = "warmup";
  EXPECT_EQ(BidsExport::stem(r), "sub-p01_task-hemiroll_tracksys-hemiroll");
  r.meta.participant = "--";
  EXPECT_THROW(BidsExport::stem(r), RecordError);
}

TEST(BidsExportTest, ChannelsDescribeEveryColumnOfTheMotionFile) {
  hemiroll::test::TempDirectory dir;
  const Recording r = sample();
  const BidsFiles f = BidsExport::write(r, dir.path() / "motion");
  const auto channels = tsv(f.channelsTsv);
  const auto motion = tsv(f.motionTsv);
  ASSERT_FALSE(channels.empty());
  EXPECT_EQ(channels[0], (std::vector<std::string>{"name", "component", "type", "tracked_point", "units"}));
  // BIDS motion's restricted list of channel types.
  const std::set<std::string> types = {"ACCEL", "ANGACCEL", "GYRO", "JNTANG", "LATENCY",
                                       "MAGN", "MISC", "ORNT", "POS", "VEL"};
  for (std::size_t i = 1; i < channels.size(); ++i) {
    ASSERT_EQ(channels[i].size(), 5u) << i;
    EXPECT_TRUE(types.count(channels[i][2])) << channels[i][2];
  }
  // No header: one line per row, one field per channel, every field a number
  // whose bits are the recording's (the tick column is left out).
  ASSERT_EQ(motion.size(), r.rows.size());
  for (std::size_t k = 0; k < motion.size(); ++k) {
    ASSERT_EQ(motion[k].size(), channels.size() - 1) << k;
    double time = 0.0, x_p = 0.0;
    ASSERT_TRUE(parseDouble(motion[k][0], time));
    ASSERT_TRUE(parseDouble(motion[k][1], x_p));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(time), std::bit_cast<std::uint64_t>(r.rows[k].time));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(x_p), std::bit_cast<std::uint64_t>(r.rows[k].state[0]));
  }
  EXPECT_EQ(channels.size() - 1, CsvRowFormat::columns().size() - 1);

  const auto j = nlohmann::json::parse(hemiroll::test::TempDirectory::read(f.motionJson));
  for (const char* key : {"TaskName", "SamplingFrequency", "TrackingSystemName"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_DOUBLE_EQ(j["SamplingFrequency"].get<double>(), 100.0);
  EXPECT_EQ(j["HapticGuidance"]["Kind"], "autopilot");
  EXPECT_EQ(j["HapticGuidance"]["StiffnessNPerM"].get<double>(), 300.0);
  EXPECT_EQ(j["HapticGuidance"]["Fade"].get<double>(), 0.75);
  EXPECT_EQ(j["MotionChannelCount"].get<std::size_t>(), channels.size() - 1);
  int sum = 0;
  for (const char* type : {"LATENCY", "POS", "VEL", "GYRO", "MISC"}) sum += j.value(std::string(type) + "ChannelCount", 0);
  EXPECT_EQ(static_cast<std::size_t>(sum), channels.size() - 1);
}

}  // namespace
}  // namespace hemiroll::record
