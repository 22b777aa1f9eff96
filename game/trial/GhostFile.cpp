#include "game/trial/GhostFile.h"

#include "engine/record/FileNames.h"

namespace hemiroll::game {

namespace {

// Names become file names: letters and digits kept, the rest '_'.
std::string fileStem(const std::string& name) { return record::fileStemOf(name, "", "_"); }

}  // namespace

std::filesystem::path ghostFile(const std::filesystem::path& dataDir, const std::string& levelName,
                                const std::string& player) {
  return dataDir / "ghosts" / fileStem(player) / (fileStem(levelName) + ".hrr");
}

std::string keepAsGhost(const std::filesystem::path& replay, const std::filesystem::path& ghost) {
  std::error_code ec;
  std::filesystem::create_directories(ghost.parent_path(), ec);
  const std::filesystem::path temp = ghost.string() + ".new";
  std::filesystem::copy_file(replay, temp, std::filesystem::copy_options::overwrite_existing, ec);
  if (!ec) std::filesystem::rename(temp, ghost, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(temp, ec);
    return "the best run could not be kept as the ghost " + ghost.string() + ": " + why;
  }
  return "";
}

}  // namespace hemiroll::game
