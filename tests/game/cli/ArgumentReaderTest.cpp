#include "game/cli/ArgumentReader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace hemiroll::cli {
namespace {

using ::testing::HasSubstr;

struct Parsed {
  bool fast = false;
  double step = 0.0;
  std::optional<double> tol;
  long long count = 1;
  std::string out;
  int width = 0, height = 0;
  std::vector<std::string> files;
};

std::string readInto(Parsed& p, const std::vector<std::string>& args, std::size_t files = 1) {
  ArgumentReader reader;
  reader.flag("--fast", [&] { p.fast = true; })
      .option("--dt", positiveNumber(p.step, "a positive number of seconds"))
      .option("--tol", numberIn(p.tol, 1e-16, 1.0, "a tolerance in [1e-16, 1]"))
      .option("--count", integerIn(p.count, 1, 100, "a whole number in 1..100"))
      .option("--out", text(p.out, "a file name"))
      .option("--size", size(p.width, p.height, 16, 4096))
      .positional("input file", files, [&](const std::string& f) { p.files.push_back(f); });
  return reader.read(args);
}

TEST(ArgumentReaderTest, OptionsTakeTheNextArgumentOrTheTextAfterEquals) {
  Parsed p;
  ASSERT_EQ(readInto(p, {"--dt", "0.002", "a.lua", "--tol=1e-9", "--fast", "--count=7", "--out", "x.csv",
                         "--size", "800x600"}),
            "");
  EXPECT_TRUE(p.fast);
  EXPECT_EQ(p.step, 0.002);
  EXPECT_EQ(p.tol, 1e-9);
  EXPECT_EQ(p.count, 7);
  EXPECT_EQ(p.out, "x.csv");
  EXPECT_EQ(p.width, 800);
  EXPECT_EQ(p.height, 600);
  EXPECT_EQ(p.files, std::vector<std::string>{"a.lua"});
}

TEST(ArgumentReaderTest, DoubleDashEndsTheFlagsAndDashIsPositional) {
  Parsed p;
  ASSERT_EQ(readInto(p, {"-", "--", "--fast"}, 2), "");
  EXPECT_FALSE(p.fast);
  EXPECT_EQ(p.files, (std::vector<std::string>{"-", "--fast"}));
}

TEST(ArgumentReaderTest, EveryMistakeIsOneSentenceNamingTheFlagAndTheValue) {
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {{"--dt", "abc"}, "flag --dt needs a positive number of seconds, got 'abc'"},
      {{"--dt", "0"}, "flag --dt needs a positive number of seconds, got '0'"},
      {{"--dt", "-1e-3"}, "flag --dt needs a positive number of seconds, got '-1e-3'"},
      {{"--dt", "inf"}, "flag --dt needs a positive number of seconds, got 'inf'"},
      {{"--dt", "nan"}, "flag --dt needs a positive number of seconds, got 'nan'"},
      {{"--dt", "0.001s"}, "flag --dt needs a positive number of seconds, got '0.001s'"},
      {{"--tol", "2"}, "flag --tol needs a tolerance in [1e-16, 1], got '2'"},
      {{"--count", "2.5"}, "flag --count needs a whole number in 1..100, got '2.5'"},
      {{"--count", "101"}, "flag --count needs a whole number in 1..100, got '101'"},
      {{"--count", "99999999999999999999"}, "flag --count needs a whole number in 1..100, got '99999999999999999999'"},
      {{"--out="}, "flag --out needs a file name, got ''"},
      {{"--size", "800"}, "flag --size needs WxH in pixels with both in 16..4096, got '800'"},
      {{"--size", "8x600"}, "flag --size needs WxH in pixels with both in 16..4096, got '8x600'"},
      {{"--dt"}, "flag --dt needs a value"},
      {{"--fast=yes"}, "flag --fast takes no value"},
      {{"--slow"}, "unknown flag '--slow'"},
      {{"-x"}, "unknown flag '-x'"},
      {{"a.lua", "b.lua"}, "unexpected argument 'b.lua' (only one input file)"},
  };
  for (const auto& [args, expected] : cases) {
    Parsed p;
    EXPECT_EQ(readInto(p, args), expected);
  }
}

TEST(ArgumentReaderTest, UnsignedUpToTakesDigitsOnlyAndAtMostTheMaximum) {
  std::uint64_t seed = 0;
  std::optional<std::uint64_t> maybe;
  ArgumentReader reader;
  reader.option("--seed", unsignedUpTo(seed, 0x7fffffffffffffffULL, "a seed"))
      .option("--maybe", unsignedUpTo(maybe, 10, "at most 10"));
  EXPECT_EQ(reader.read({"--seed", "9223372036854775807", "--maybe=10"}), "");
  EXPECT_EQ(seed, 0x7fffffffffffffffULL);
  EXPECT_EQ(maybe, 10u);
  EXPECT_EQ(reader.read({"--seed", "9223372036854775808"}), "flag --seed needs a seed, got '9223372036854775808'");
  EXPECT_EQ(reader.read({"--maybe", "11"}), "flag --maybe needs at most 10, got '11'");
  for (const std::string bad : {"-1", "1.5", "", "+3", "0x10"})
    EXPECT_EQ(reader.read({"--seed", bad}), "flag --seed needs a seed, got '" + bad + "'");
}

TEST(ArgumentReaderTest, TheFirstErrorStopsTheReading) {
  Parsed p;
  EXPECT_THAT(readInto(p, {"--dt", "x", "--fast"}), HasSubstr("--dt"));
  EXPECT_FALSE(p.fast);
}

TEST(ArgumentReaderTest, CommandsWithoutPositionalsSayTheArgumentIsUnexpected) {
  bool help = false;
  ArgumentReader reader;
  reader.flag("--help", [&] { help = true; });
  EXPECT_EQ(reader.read({"stray"}), "unexpected argument 'stray'");
  EXPECT_EQ(reader.read({"--help"}), "");
  EXPECT_TRUE(help);
}

TEST(ArgumentReaderTest, ValueReadersTakeOnlyWholeTexts) {
  double x = 0.0;
  EXPECT_TRUE(readNumber("+1.5e-3", x));
  EXPECT_EQ(x, 1.5e-3);
  EXPECT_TRUE(readNumber("-2", x));
  EXPECT_EQ(x, -2.0);
  for (const char* bad : {"", "+", "-", "+-1", "1.0.0", " 1", "1 ", "1e400", "0x10", "nan", "-inf"})
    EXPECT_FALSE(readNumber(bad, x)) << bad;

  long long n = 0;
  EXPECT_TRUE(readInteger("-42", n));
  EXPECT_EQ(n, -42);
  EXPECT_FALSE(readInteger("4.0", n));
  unsigned long long u = 0;
  EXPECT_TRUE(readUnsigned("18446744073709551615", u));
  EXPECT_EQ(u, std::numeric_limits<unsigned long long>::max());
  EXPECT_FALSE(readUnsigned("-1", u));
  EXPECT_FALSE(readUnsigned("+1", u));

  std::array<double, 3> v{};
  EXPECT_TRUE(readNumbers("0.01,-0.02,3", v));
  EXPECT_EQ(v, (std::array<double, 3>{0.01, -0.02, 3.0}));
  EXPECT_FALSE(readNumbers("1,2", v));
  EXPECT_FALSE(readNumbers("1,2,3,", v));
  EXPECT_EQ(splitList("a,,b", ','), (std::vector<std::string>{"a", "", "b"}));
  EXPECT_EQ(splitList("", ','), (std::vector<std::string>{""}));
}

}  // namespace
}  // namespace hemiroll::cli
