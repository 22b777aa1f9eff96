#include "game/view/AssetsDirectory.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

namespace hemiroll::game {

std::string findAssetsDirectory() {
  namespace fs = std::filesystem;
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("HEMIROLL_ASSETS"); env && *env) candidates.emplace_back(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(exe.parent_path() / "assets");
    candidates.push_back(exe.parent_path().parent_path() / "assets");
  }
  candidates.emplace_back("assets");
  for (const fs::path& c : candidates)
    if (fs::is_directory(c / "shaders", ec)) return c.string();
  return "";
}

}  // namespace hemiroll::game
