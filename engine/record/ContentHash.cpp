#include "engine/record/ContentHash.h"

#include <cstdio>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/record/ReplayFormat.h"

namespace hemiroll::record {

std::string contentHash(std::string_view bytes) {
  const std::uint64_t h = fnv1a(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), kFnvOffset);
  char text[32];
  std::snprintf(text, sizeof text, "fnv1a-%016llx", static_cast<unsigned long long>(h));
  return text;
}

std::string fileContentHash(const std::string& path) {
  try {
    return contentHash(files::readCheckedFile(path, files::kLuaSource));
  } catch (const files::FileReadError&) {
    return "";
  }
}

}  // namespace hemiroll::record
