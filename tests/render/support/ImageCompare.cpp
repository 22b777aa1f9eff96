#include "tests/render/support/ImageCompare.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "engine/render/RenderError.h"

namespace hemiroll::test {

ImageDifference compareImages(const render::Image& a, const render::Image& b) {
  ImageDifference d;
  d.sameSize = a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size();
  if (!d.sameSize || a.rgba.empty()) return d;
  std::size_t differing = 0;
  int maxDiff = 0;
  for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
    int pixelMax = 0;
    for (int c = 0; c < 4; ++c) pixelMax = std::max(pixelMax, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
    maxDiff = std::max(maxDiff, pixelMax);
    differing += pixelMax > kChannelTolerance;
  }
  d.differingFraction = double(differing) / double(a.rgba.size() / 4);
  d.maxChannelDifference = maxDiff;
  return d;
}

::testing::AssertionResult matchesReference(const render::Image& image, const std::string& name) {
  const std::string path = std::string(HEMIROLL_SOURCE_DIR) + "/tests/render/reference/" + name + ".png";
  const char* update = std::getenv("HEMIROLL_UPDATE_REFERENCES");
  if (update && std::strcmp(update, "1") == 0) {
    render::writePng(path, image);
    return ::testing::AssertionSuccess() << "wrote " << path;
  }
  render::Image reference;
  try {
    reference = render::readPng(path);
  } catch (const render::RenderError& e) {
    return ::testing::AssertionFailure() << e.what() << " (HEMIROLL_UPDATE_REFERENCES=1 writes it)";
  }
  const ImageDifference d = compareImages(image, reference);
  if (d.matches()) return ::testing::AssertionSuccess();
  render::writePng(name + ".actual.png", image);
  return ::testing::AssertionFailure() << name << ": " << d.differingFraction * 100.0 << " % of pixels differ by more than "
                                       << kChannelTolerance << " (max " << d.maxChannelDifference << "; allowed "
                                       << kMaxDifferingFraction * 100.0 << " %); the image is in " << name
                                       << ".actual.png";
}

}  // namespace hemiroll::test
