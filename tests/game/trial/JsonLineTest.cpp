// game/trial/JsonLine: one JSON object per line, strings escaped per RFC 8259,
// numbers that read back to the same double, null for non-finite numbers.

#include "game/trial/JsonLine.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>

namespace hemiroll::game {
namespace {

TEST(JsonLine, WritesKeysInOrder) {
  JsonLine line;
  line.add("level", "a.lua").add("ticks", 12LL).add("time", 0.5).addNull("score");
  EXPECT_EQ(line.str(), R"({"level":"a.lua","ticks":12,"time":0.5,"score":null})");
}

TEST(JsonLine, BooleansAreBareWords) {
  JsonLine line;
  line.addBool("complete", true).addBool("stopped", false).add("name", "true");
  EXPECT_EQ(line.str(), R"({"complete":true,"stopped":false,"name":"true"})");
}

TEST(JsonLine, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(JsonLine::quote("say \"hi\"\\now\n\t\x01"), R"("say \"hi\"\\now\n\t\u0001")");
  EXPECT_EQ(JsonLine::quote("r\xC3\xA9sum\xC3\xA9"), "\"r\xC3\xA9sum\xC3\xA9\"") << "UTF-8 passes through";
}

// Bytes that are not UTF-8 would make the line invalid JSON: each is
// written as \xNN (its backslash escaped as JSON's), the rest as it is.
TEST(JsonLine, BytesThatAreNotUtf8AreWrittenAsHex) {
  EXPECT_EQ(JsonLine::quote("lev\xFF.lua"), "\"lev\\\\xFF.lua\"");
  EXPECT_EQ(JsonLine::quote("\xC3\xA4 ok"), "\"\xC3\xA4 ok\"");  // valid UTF-8 kept
  EXPECT_EQ(JsonLine::quote("a\nb"), "\"a\\nb\"");             // controls as JSON writes them
}

TEST(JsonLine, NonFiniteNumbersAreNull) {
  EXPECT_EQ(JsonLine::number(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(JsonLine::number(std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(JsonLine::number(-std::numeric_limits<double>::infinity()), "null");
}

TEST(JsonLine, NumbersReadBackExactly) {
  for (const double v : {0.1, 1.0 / 3.0, 5.000000000000004, -2.5e-300, 1e300}) {
    const std::string text = JsonLine::number(v);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
  }
  EXPECT_EQ(JsonLine::number(0.1), "0.1");  // the shortest such form
  EXPECT_EQ(JsonLine::number(0.25), "0.25");
}

// A time summed tick by tick reads as the tick's time, not the sum's rounding.
TEST(JsonLine, RoundedNumbersDropTrailingZeros) {
  double t = 0.0;
  for (int i = 0; i < 9358; ++i) t += 0.001;
  ASSERT_NE(JsonLine::number(t), "9.358");
  EXPECT_EQ(JsonLine::number(t, 6), "9.358");
  EXPECT_EQ(JsonLine::number(60.0, 6), "60");
  EXPECT_EQ(JsonLine::number(-1e-9, 6), "0");
  EXPECT_EQ(JsonLine::number(0.1234567, 3), "0.123");
  EXPECT_EQ(JsonLine::number(std::numeric_limits<double>::quiet_NaN(), 6), "null");
  JsonLine line;
  line.add("time", t, 6);
  EXPECT_EQ(line.str(), R"({"time":9.358})");
}

}  // namespace
}  // namespace hemiroll::game
