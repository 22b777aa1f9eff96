#include "engine/render/Image.h"

#include <gtest/gtest.h>

#include "engine/render/RenderError.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::render {
namespace {

TEST(ImageTest, PngRoundTripKeepsEveryByte) {
  Image image;
  image.width = 5;
  image.height = 3;
  for (int i = 0; i < 5 * 3 * 4; ++i) image.rgba.push_back(std::uint8_t(i * 17));
  test::TempDirectory dir;
  const std::string path = (dir.path() / "a.png").string();
  writePng(path, image);
  const Image back = readPng(path);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgba, image.rgba);  // PNG is lossless
  EXPECT_EQ(back.pixel(1, 2)[0], image.rgba[(2 * 5 + 1) * 4]);
}

TEST(ImageTest, ErrorsNameTheFile) {
  Image image{2, 2, std::vector<std::uint8_t>(16, 0)};
  try {
    writePng("/nonexistent-dir/x.png", image);
    FAIL() << "wrote into a missing directory";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.png"), std::string::npos) << e.what();
  }
  test::TempDirectory dir;
  const std::string notPng = dir.write("not.png", "hello");
  try {
    readPng(notPng);
    FAIL() << "read a text file as a PNG";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find(notPng), std::string::npos) << e.what();
  }
  EXPECT_THROW(writePng(notPng, Image{}), RenderError);
}

}  // namespace
}  // namespace hemiroll::render
