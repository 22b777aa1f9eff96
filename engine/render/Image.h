#pragma once
// An RGBA8 image, rows from the top (as PNG files and screens are; GL reads
// bottom-up, Framebuffer::read flips). PNG in and out through Debian's stb
// (libstb-dev).

#include <cstdint>
#include <string>
#include <vector>

namespace hemiroll::render {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4

  const std::uint8_t* pixel(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

// Throws RenderError naming the file when it cannot be written or read.
void writePng(const std::string& path, const Image& image);
Image readPng(const std::string& path);

}  // namespace hemiroll::render
