#include "engine/render/Image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cerrno>
#include <cstring>

#include "engine/render/RenderError.h"

namespace hemiroll::render {

void writePng(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() != std::size_t(image.width) * image.height * 4)
    throw RenderError(path + ": nothing to write (empty image)");
  errno = 0;
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw RenderError(path + ": cannot write the PNG" + (errno ? std::string(" (") + std::strerror(errno) + ")" : ""));
}

Image readPng(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) throw RenderError(path + ": cannot read the image (" + stbi_failure_reason() + ")");
  Image image;
  image.width = w;
  image.height = h;
  image.rgba.assign(data, data + std::size_t(w) * h * 4);
  stbi_image_free(data);
  return image;
}

}  // namespace hemiroll::render
