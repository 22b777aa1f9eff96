#include "game/trial/GhostFile.h"

#include <cctype>
#include <cmath>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/FileNames.h"
#include "engine/record/RecordError.h"
#include "game/trial/JsonLine.h"

namespace hemiroll::game {

namespace {

// Names become file names: letters and digits kept, the rest '_'.
std::string fileStem(const std::string& name) { return record::fileStemOf(name, "", "_"); }

}  // namespace

std::filesystem::path ghostFile(const std::filesystem::path& dataDir, const std::string& levelName,
                                const std::string& player) {
  return dataDir / "ghosts" / fileStem(player) / (fileStem(levelName) + ".hrr");
}

std::string keepAsGhost(const std::filesystem::path& replay, const std::filesystem::path& ghost, double time) {
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
  try {
    record::writeFileAtomically(ghost.string() + ".time", JsonLine::number(time) + "\n");
  } catch (const record::RecordError& e) {
    return std::string("the ghost's time could not be kept: ") + e.what();
  }
  return "";
}

std::optional<double> ghostTime(const std::filesystem::path& ghost) {
  std::string text;
  try {
    text = record::readWholeFile(ghost.string() + ".time", files::kGhostTime);
  } catch (const record::RecordError&) {
    return std::nullopt;  // missing, not a regular file, or too large: no time shown
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
  double time = 0.0;
  if (!record::parseDouble(text, time) || !std::isfinite(time) || time < 0.0) return std::nullopt;
  return time;
}

std::string keepGhostOwner(const std::filesystem::path& ghost, GhostOwner owner) {
  try {
    record::writeFileAtomically(ghost.string() + ".by", owner == GhostOwner::Autopilot ? "autopilot\n" : "player\n");
  } catch (const record::RecordError& e) {
    return std::string("whose ghost it is could not be kept: ") + e.what();
  }
  return "";
}

GhostOwner ghostOwner(const std::filesystem::path& ghost) {
  // A missing, odd or unreadable file leaves the ghost the player's: the
  // label is all it decides.
  const std::filesystem::path by = ghost.string() + ".by";
  std::error_code ec;
  if (!std::filesystem::exists(by, ec)) return GhostOwner::Player;
  std::string word;
  try {
    word = files::readCheckedFile(by, files::kGhostOwner);
  } catch (const files::FileReadError&) {
    return GhostOwner::Player;
  }
  while (!word.empty() && std::isspace(static_cast<unsigned char>(word.back()))) word.pop_back();
  return word == "autopilot" ? GhostOwner::Autopilot : GhostOwner::Player;
}

}  // namespace hemiroll::game
