// game/research/sweep/SweepTable: the CSV's columns (SI suffixes, unique), rows of
// the header's length with empty cells for what was not found and never
// NaN, and the reader that refuses other files.

#include "game/research/sweep/SweepTable.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

#include "engine/record/CsvRowFormat.h"
#include "game/research/sweep/SweepError.h"
#include "tests/game/support/TinySweep.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(SweepTable, ColumnsAreUniqueAndCarryTheirUnit) {
  const auto& c = sweepColumns();
  EXPECT_EQ(std::set<std::string>(c.begin(), c.end()).size(), c.size());
  EXPECT_EQ(c.front(), "point");
  for (const char* name : {"R_m", "m_s_kg", "m_p_kg", "g_m_per_s2", "r1_m", "r2_m", "Omega_rad_per_s", "event_time_s",
                           "max_tilt_rad", "steady_rate_rad_per_s", "arc_curvature_per_m", "drift_speed_m_per_s"})
    EXPECT_NO_THROW(sweepColumn(name)) << name;
  EXPECT_THROW(sweepColumn("drift"), std::out_of_range);
  EXPECT_EQ(sweepHeader(), record::csvLine(c));
}

// Split on commas outside quotes (the notes may hold commas).
std::size_t fieldCount(const std::string& line) {
  std::size_t n = 1;
  bool quoted = false;
  for (const char ch : line) {
    if (ch == '"') quoted = !quoted;
    if (ch == ',' && !quoted) ++n;
  }
  return n;
}

TEST(SweepTable, RowsHaveEveryColumnAndNoNaN) {
  const SweepGrid grid(test::sweepOf(test::kTippingSweep));
  for (const long long i : {0LL, 3LL}) {  // runs to the end, tips over
    const SweepPoint p = grid.point(i);
    const PointMeasurement m = measurePoint(grid, p);
    const std::string row = sweepRow(p, m);
    ASSERT_EQ(row.back(), '\n');
    EXPECT_EQ(row.find('\n'), row.size() - 1);  // one line: a cut partial file is cut at line ends
    EXPECT_EQ(fieldCount(row.substr(0, row.size() - 1)), sweepColumns().size());
    EXPECT_THAT(row, Not(HasSubstr("nan")));
    EXPECT_THAT(row, Not(HasSubstr("inf")));
    EXPECT_EQ(row.rfind(std::to_string(i) + ",", 0), 0u);
  }
  const PointMeasurement tipped = measurePoint(grid, grid.point(3));
  const std::string row = sweepRow(grid.point(3), tipped);
  EXPECT_THAT(row, HasSubstr(",tipped_over,0.38"));  // the event and its time
}

TEST(SweepTable, TheReaderRefusesOtherColumns) {
  const test::TempDirectory dir;
  const std::string other = dir.write("other.csv", "a,b\n1,2\n");
  try {
    readSweepRows(other);
    FAIL();
  } catch (const SweepError& e) {
    EXPECT_EQ(e.kind(), SweepError::Kind::BadInput);
    EXPECT_THAT(e.what(), HasSubstr("other.csv: its columns are not this program's sweep columns"));
  }
  EXPECT_THROW(readSweepRows(dir.path() / "missing.csv"), SweepError);
  const std::string cut = dir.write("cut.csv", sweepHeader() + "0,1,2");
  EXPECT_THROW(readSweepRows(cut), SweepError);  // the last row has no line end
}

}  // namespace
}  // namespace hemiroll::game
