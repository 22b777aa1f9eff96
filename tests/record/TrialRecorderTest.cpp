#include "engine/record/TrialRecorder.h"

#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "tests/record/support/RecordRows.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

nlohmann::json sidecarOf(const TrialRecorder& rec) { return nlohmann::json::parse(hemiroll::test::TempDirectory::read(rec.sidecarPath())); }

std::size_t lines(const std::filesystem::path& path) {
  const std::string text = hemiroll::test::TempDirectory::read(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(TrialRecorderTest, SidecarSaysIncompleteUntilFinished) {
  hemiroll::test::TempDirectory dir;
  TrialMeta meta;
  meta.trialId = "t1";
  TrialRecorder rec(dir.path(), meta);
  EXPECT_EQ(sidecarOf(rec)["complete"], false);
  EXPECT_TRUE(sidecarOf(rec)["outcome"].is_null());
  for (const auto& row : test::randomRows(25, 1)) rec.push(row);
  TrialEnd end;
  end.outcome = "success";
  end.reason = "goal reached";
  end.droppedRows = 3;
  rec.finish(end);
  const nlohmann::json j = sidecarOf(rec);
  EXPECT_EQ(j["complete"], true);
  EXPECT_EQ(j["rows"], 25);
  EXPECT_EQ(j["dropped_rows"], 3);
  EXPECT_EQ(j["outcome"]["result"], "success");
  EXPECT_EQ(j["software"]["version"], softwareVersion());
  EXPECT_EQ(lines(rec.csvPath()), 26u);  // header + rows
  // The atomic rewrite leaves no temporary behind.
  EXPECT_FALSE(std::filesystem::exists(rec.sidecarPath().string() + ".tmp"));
  EXPECT_THROW(rec.finish(end), RecordError);
}

TEST(TrialRecorderTest, WithoutFinishTheTrialStaysIncompleteButItsRowsAreKept) {
  hemiroll::test::TempDirectory dir;
  std::filesystem::path csv;
  {
    TrialMeta meta;
    meta.trialId = "t2";
    TrialRecorder rec(dir.path(), meta);
    for (const auto& row : test::randomRows(10, 2)) rec.push(row);
    csv = rec.csvPath();
  }
  const Recording r = RecordingReader::load(csv);
  EXPECT_FALSE(r.status.complete);
  EXPECT_EQ(r.rows.size(), 10u);
}

TEST(TrialRecorderTest, WriterThreadDrainsTheRingAndCountsTickGaps) {
  hemiroll::test::TempDirectory dir;
  TrialMeta meta;
  meta.trialId = "t3";
  meta.recordEvery = 10;
  TrialRecorder rec(dir.path(), meta);
  auto ring = std::make_unique<haptics::RecordRing>();
  rec.startWriter(*ring);
  std::vector<haptics::RecordRow> rows = test::randomRows(3000, 3);
  rows.erase(rows.begin() + 100);  // one row lost: the next tick is 20 after its predecessor
  for (const auto& row : rows)
    while (!ring->push(row)) std::this_thread::yield();  // the producer outpaces the writer here
  rec.finish(TrialEnd{});
  EXPECT_EQ(rec.rows(), rows.size());
  EXPECT_EQ(rec.tickGaps(), 1u);
  const Recording back = RecordingReader::load(rec.csvPath());
  ASSERT_EQ(back.rows.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) ASSERT_TRUE(test::sameBits(rows[i], back.rows[i])) << i;
}

TEST(TrialRecorderTest, RowsReachTheFileWithinTheFlushInterval) {
  hemiroll::test::TempDirectory dir;
  TrialMeta meta;
  meta.trialId = "t4";
  RecorderOptions options;
  options.flushInterval = 0.05;
  TrialRecorder rec(dir.path(), meta, options);
  auto ring = std::make_unique<haptics::RecordRing>();
  rec.startWriter(*ring);
  for (const auto& row : test::randomRows(5, 4)) ring->push(row);
  // No more rows arrive; the writer must still flush what it has. 2 s is
  // 40 flush intervals: only a machine stalled for seconds misses it.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (lines(rec.csvPath()) < 6 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(lines(rec.csvPath()), 6u);
  rec.finish(TrialEnd{});
}

TEST(TrialRecorderTest, RejectsUnsafeTrialIdsAndMissingFolders) {
  hemiroll::test::TempDirectory dir;
  for (const char* id : {"", "..", "a/b", "trial 1", "x;rm"}) {
    TrialMeta meta;
    meta.trialId = id;
    EXPECT_THROW(TrialRecorder(dir.path(), meta), RecordError) << id;
  }
  TrialMeta meta;
  try {
    TrialRecorder rec(dir.path() / "missing", meta);
    FAIL() << "no error for a missing folder";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
  }
}

TEST(TrialRecorderTest, NeverOverwritesAnEarlierTrial) {
  hemiroll::test::TempDirectory dir;
  TrialMeta meta;
  meta.trialId = "t6";
  {
    TrialRecorder first(dir.path(), meta);
    first.push(test::randomRows(1, 6)[0]);
    first.finish(TrialEnd{});
  }
  const std::string before = hemiroll::test::TempDirectory::read(dir.path() / "t6.csv");
  try {
    TrialRecorder second(dir.path(), meta);
    FAIL() << "no error";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("t6.json: already exists"), std::string::npos) << e.what();
  }
  EXPECT_EQ(hemiroll::test::TempDirectory::read(dir.path() / "t6.csv"), before);
  EXPECT_TRUE(RecordingReader::load(dir.path() / "t6.csv").status.complete);
  // A CSV alone (its sidecar lost) is not overwritten either.
  std::filesystem::remove(dir.path() / "t6.json");
  try {
    TrialRecorder third(dir.path(), meta);
    FAIL() << "no error";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("t6.csv: already exists"), std::string::npos) << e.what();
  }
  EXPECT_EQ(hemiroll::test::TempDirectory::read(dir.path() / "t6.csv"), before);
}

TEST(TrialRecorderTest, IsMovable) {
  hemiroll::test::TempDirectory dir;
  TrialMeta meta;
  meta.trialId = "t5";
  TrialRecorder a(dir.path(), meta);
  a.push(test::randomRows(1, 5)[0]);
  TrialRecorder b = std::move(a);
  b.push(test::randomRows(2, 5)[1]);
  b.finish(TrialEnd{});
  EXPECT_EQ(RecordingReader::load(b.csvPath()).rows.size(), 2u);
}

}  // namespace
}  // namespace hemiroll::record
