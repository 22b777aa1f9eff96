#include "game/ui/view/ShippedDirectories.h"

#include <cstdlib>
#include <system_error>

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

// Beside the program, and one level up (build/hemiroll in a checkout).
void addBesideProgram(const fs::path& program, const char* name, std::vector<fs::path>& out) {
  if (program.empty()) return;
  out.push_back(program.parent_path() / name);
  out.push_back(program.parent_path().parent_path() / name);
}

bool holdsLevels(const fs::path& dir) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".lua" && it->is_regular_file(ec)) return true;
  return false;
}

}  // namespace

fs::path programPath() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

std::string findAssetsDirectory() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("HEMIROLL_ASSETS"); env && *env) candidates.emplace_back(env);
  addBesideProgram(programPath(), "assets", candidates);
  candidates.emplace_back("assets");
  std::error_code ec;
  for (const fs::path& c : candidates)
    if (fs::is_directory(c / "shaders", ec)) return c.string();
  return "";
}

std::vector<fs::path> levelsDirectoryCandidates(const fs::path& program) {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("HEMIROLL_LEVELS"); env && *env) candidates.emplace_back(env);
  candidates.emplace_back("levels");
  addBesideProgram(program, "levels", candidates);
  return candidates;
}

std::string findLevelsDirectory(const fs::path& program) {
  for (const fs::path& c : levelsDirectoryCandidates(program))
    if (holdsLevels(c)) return c.string();
  return "";
}

std::string resolveLevelPath(const std::string& level, const std::string& levelsDir) {
  std::error_code ec;
  if (level.empty() || fs::exists(level, ec) || levelsDir.empty()) return level;
  const fs::path shipped = fs::path(levelsDir) / fs::path(level).filename();
  return fs::is_regular_file(shipped, ec) ? shipped.string() : level;
}

}  // namespace hemiroll::game
