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
}

}  // namespace
}  // namespace hemiroll::game
