#include "engine/record/DataDirectory.h"

#include <cstdlib>

namespace hemiroll::record {

std::filesystem::path dataDirectory() {
  if (const char* d = std::getenv("HEMIROLL_DATA_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_DATA_HOME"); x && *x) return std::filesystem::path(x) / "hemiroll";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".local/share/hemiroll";
  return std::filesystem::path(".hemiroll");
}

}  // namespace hemiroll::record
