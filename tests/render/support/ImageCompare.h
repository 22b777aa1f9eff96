#pragma once
// Image comparison for render tests, and the reference images' home.
//
// Tolerance: a pixel "differs" when any channel differs by more than
// kChannelTolerance counts; images match when at most kMaxDifferingFraction
// of their pixels differ. Why these numbers: llvmpipe renders the same scene
// bit for bit on one machine, but another Mesa/LLVM version may round
// lighting by a few counts (16/255 covers it) and move edge pixels of
// silhouettes and 1-pixel lines (0.5 % of a 320x240 image is 384 pixels,
// about the length of the scene's edges); a real change (a marker moved or
// missing, the hemisphere turned) changes thousands.

#include <gtest/gtest.h>

#include <string>

#include "engine/render/Image.h"

namespace hemiroll::test {

inline constexpr int kChannelTolerance = 16;
inline constexpr double kMaxDifferingFraction = 0.005;

struct ImageDifference {
  bool sameSize = false;
  double differingFraction = 1.0;  // of all pixels
  int maxChannelDifference = 255;
  bool matches() const { return sameSize && differingFraction <= kMaxDifferingFraction; }
};

ImageDifference compareImages(const render::Image& a, const render::Image& b);

// tests/render/reference/NAME.png. With HEMIROLL_UPDATE_REFERENCES=1 in the
// environment the image is written there instead and the check passes
// (regenerate after an intended visual change; review the PNGs in the diff).
// Otherwise the image is also written to the working directory as
// NAME.actual.png when it does not match, for inspection.
::testing::AssertionResult matchesReference(const render::Image& image, const std::string& name);

}  // namespace hemiroll::test
