#include "engine/record/ContentHash.h"

#include <cstdio>
#include <fstream>
#include <iterator>

#include "engine/record/ReplayFormat.h"

namespace hemiroll::record {

std::string contentHash(std::string_view bytes) {
  const std::uint64_t h = fnv1a(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), kFnvOffset);
  char text[32];
  std::snprintf(text, sizeof text, "fnv1a-%016llx", static_cast<unsigned long long>(h));
  return text;
}

std::string fileContentHash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return contentHash(bytes);
}

}  // namespace hemiroll::record
