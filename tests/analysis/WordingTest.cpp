// engine/analysis Wording: numbers in reasons, never "nan".

#include <gtest/gtest.h>

#include <limits>

#include "engine/analysis/Wording.h"

namespace hemiroll::analysis {
namespace {

TEST(Wording, ThreeSignificantDigitsAndWordsForNonFinite) {
  EXPECT_EQ(shortNumber(0.012345), "0.0123");
  EXPECT_EQ(shortNumber(-8.6076), "-8.61");
  EXPECT_EQ(shortNumber(35.0), "35");
  EXPECT_EQ(shortNumber(std::numeric_limits<double>::quiet_NaN()), "not a number");
  EXPECT_EQ(shortNumber(-std::numeric_limits<double>::infinity()), "minus infinite");
}

}  // namespace
}  // namespace hemiroll::analysis
