// game/research/analysis SimCsvReader: `hemiroll sim` CSVs read back, errors naming file:line.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "game/research/analysis/AnalysisInputError.h"
#include "game/research/analysis/SimCsvReader.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

constexpr const char* kHeader = "t,x_p,y_p,xd_p,yd_p,w_x,w_y,w_z,u_a,v_a,u_o,v_o,psi,energy,f_x,f_y\n";

std::string errorOf(const std::string& path) {
  try {
    readSimCsv(path);
  } catch (const AnalysisInputError& e) {
    return e.what();
  }
  return "";
}

TEST(SimCsvReader, ReadsTheColumnsTheAnalysisNeeds) {
  const test::TempDirectory dir;
  const std::string path = dir.write("run.csv", std::string(kHeader) +
                                                    "0,0.023,0,0,0,0,0,0,0,0,0,0,0,0.5,0,0\n"
                                                    "0.001,0.0229,0.0001,0,0,0,0,0,1e-5,-2e-5,0,0,-0.001,0.5,0,0\n");
  EXPECT_TRUE(isSimCsvHeader("t,x_p,y_p,xd_p"));
  EXPECT_FALSE(isSimCsvHeader("time_s,tick,x_p_m"));
  const TrialData t = readSimCsv(path);
  ASSERT_EQ(t.time.size(), 2u);
  EXPECT_EQ(t.kind, "sim");
  EXPECT_DOUBLE_EQ(t.time[1], 0.001);
  EXPECT_DOUBLE_EQ(t.massX[1], 0.0229);
  EXPECT_DOUBLE_EQ(t.massY[1], 0.0001);
  EXPECT_DOUBLE_EQ(t.contactX[1], 1e-5);
  EXPECT_DOUBLE_EQ(t.contactY[1], -2e-5);
  EXPECT_DOUBLE_EQ(t.psi[1], -0.001);
  EXPECT_TRUE(t.notes.empty());
}

TEST(SimCsvReader, ACutLastLineIsDroppedWithANote) {
  const test::TempDirectory dir;
  const std::string path =
      dir.write("cut.csv", std::string(kHeader) + "0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n0.001,0.02,0,0,0");
  const TrialData t = readSimCsv(path);
  EXPECT_EQ(t.time.size(), 1u);
  ASSERT_EQ(t.notes.size(), 1u);
  EXPECT_THAT(t.notes[0], HasSubstr("line 3"));
}

TEST(SimCsvReader, BrokenFilesNameFileLineAndColumn) {
  const test::TempDirectory dir;
  EXPECT_THAT(errorOf(dir.write("a.csv", std::string(kHeader) + "0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n0.001,x,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n")),
              HasSubstr("a.csv:3: column 2 (x_p): 'x' is not a number"));
  EXPECT_THAT(errorOf(dir.write("b.csv", std::string(kHeader) + "0,0,0\n")), HasSubstr("b.csv:2: 3 fields, the header names 16"));
  EXPECT_THAT(errorOf(dir.write("c.csv", "t,x_p,y_p,u_a\n0,0,0,0\n")), HasSubstr("c.csv:1: no column 'v_a'"));
  EXPECT_THAT(errorOf(dir.write("d.csv", kHeader)), HasSubstr("d.csv:2: no rows"));
  EXPECT_THAT(errorOf((dir.path() / "missing.csv").string()), HasSubstr("missing.csv"));
}

}  // namespace
}  // namespace hemiroll::game
