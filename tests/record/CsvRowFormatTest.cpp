#include "engine/record/CsvRowFormat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/record/support/RecordRows.h"

namespace hemiroll::record {
namespace {

TEST(CsvRowFormatTest, EveryColumnNamedOnceWithItsUnit) {
  const auto& c = CsvRowFormat::columns();
  // time, tick, 12 states, 5 triples, 4 doubles, 5 codes, then the guidance triple.
  EXPECT_EQ(c.size(), 2u + 12u + 15u + 4u + 5u + 3u);
  EXPECT_EQ(kColumnsBeforeGuidance, c.size() - 3u);
  EXPECT_EQ(c[kColumnsBeforeGuidance - 1], "force_clamped");
  EXPECT_EQ(c[kColumnsBeforeGuidance], "Fguide_x_N");
  EXPECT_EQ(c.front(), "time_s");
  EXPECT_EQ(c[2], "x_p_m");
  EXPECT_EQ(c[13], "psi_rad");
  EXPECT_EQ(std::count(c.begin(), c.end(), "Fh_x_N"), 1);
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j) EXPECT_NE(c[i], c[j]);
  EXPECT_EQ(CsvRowFormat::header().back(), '\n');
}

TEST(CsvRowFormatTest, RandomBitPatternsRoundTripExactly) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const haptics::RecordRow row = test::randomRow(rng, static_cast<std::uint64_t>(i) * 10);
    std::string line;
    CsvRowFormat::append(row, line);
    ASSERT_EQ(line.back(), '\n');
    ASSERT_EQ(line.find('\n'), line.size() - 1);
    haptics::RecordRow back;
    ASSERT_EQ(CsvRowFormat::parse(std::string_view(line).substr(0, line.size() - 1), back), "");
    ASSERT_TRUE(test::sameBits(row, back)) << line;
  }
}

// A file written before the guidance columns reads back, with no guidance
// force; this build's lines with a guidance force keep it exactly.
TEST(CsvRowFormatTest, LinesFromBeforeGuidanceReadWithZeroGuidance) {
  std::mt19937_64 rng(14);
  haptics::RecordRow row = test::randomRow(rng, 10);
  row.guidanceForce = {0.5, -0.25, 1e-300};
  std::string line;
  CsvRowFormat::append(row, line);
  line.pop_back();
  haptics::RecordRow back;
  ASSERT_EQ(CsvRowFormat::parse(line, back), "");
  EXPECT_EQ(back.guidanceForce, row.guidanceForce);
  // Cut the three guidance fields: the old layout.
  std::string old = line;
  for (int i = 0; i < 3; ++i) old.erase(old.rfind(','));
  ASSERT_EQ(CsvRowFormat::parse(old, back), "");
  EXPECT_EQ(back.guidanceForce, (haptics::Triple{0.0, 0.0, 0.0}));
  row.guidanceForce = {};
  EXPECT_TRUE(test::sameBits(row, back));
  EXPECT_TRUE(CsvRowFormat::knownColumns(std::vector<std::string>(
      CsvRowFormat::columns().begin(), CsvRowFormat::columns().begin() + kColumnsBeforeGuidance)));
  // One field short of either layout is refused, naming the count.
  old.erase(old.rfind(','));
  EXPECT_EQ(CsvRowFormat::parse(old, back).find("37 fields, expected 41"), 0u);
}

TEST(CsvRowFormatTest, EdgeValuesRoundTripExactly) {
  for (const double v : {0.0, -0.0, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(),
                         std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), 0.1 + 0.2,
                         1.0 / 3.0}) {
    std::string text;
    appendDouble(v, text);
    double back = 1.0;
    ASSERT_TRUE(parseDouble(text, back)) << text;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(v)) << text;
  }
}

// A model that went non-finite is recorded as such (the text of NaN carries
// no payload, so only its class and the sign of infinities are kept).
TEST(CsvRowFormatTest, NonFiniteValuesStayNonFinite) {
  for (const double v : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity()}) {
    std::string text;
    appendDouble(v, text);
    double back = 0.0;
    ASSERT_TRUE(parseDouble(text, back)) << text;
    EXPECT_EQ(std::isnan(back), std::isnan(v)) << text;
    if (!std::isnan(v)) {
      EXPECT_EQ(back, v) << text;
    }
  }
}

TEST(CsvRowFormatTest, BadFieldsAreNamed) {
  std::string line;
  CsvRowFormat::append(haptics::RecordRow{}, line);
  line.pop_back();
  haptics::RecordRow row;
  // Fields edited one by one, then joined again.
  std::vector<std::string> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const auto join = [](const std::vector<std::string>& f) {
    std::string out;
    for (const std::string& x : f) {
      if (!out.empty()) out += ',';
      out += x;
    }
    return out;
  };
  // A letter in the third column (x_p_m).
  std::vector<std::string> edited = fields;
  edited[2].push_back('x');
  const std::string bad = join(edited);
  EXPECT_NE(CsvRowFormat::parse(bad, row).find("column 3 (x_p_m)"), std::string::npos) << CsvRowFormat::parse(bad, row);
  // One field short.
  EXPECT_NE(CsvRowFormat::parse(line.substr(0, line.rfind(',')), row).find("fields, expected"), std::string::npos);
  // An enum code out of range (fault is the third last column before the guidance triple).
  edited = fields;
  edited[kColumnsBeforeGuidance - 3] = std::to_string(kFaultCodes);
  const std::string code = join(edited);
  EXPECT_NE(CsvRowFormat::parse(code, row).find("(fault)"), std::string::npos) << CsvRowFormat::parse(code, row);
  EXPECT_FALSE(parseDouble("1.0x", row.time));
  EXPECT_FALSE(parseDouble("", row.time));
}

}  // namespace
}  // namespace hemiroll::record
