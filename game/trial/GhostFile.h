#pragma once
// Where a player's best run of a level is kept for racing: a replay log at
// <data dir>/ghosts/<player>/<level name>.hrr, replaced when the player
// beats it. The log carries the level's hash, so a ghost of an older version
// of the level is refused when loaded (ReplayPlayer), not raced.

#include <filesystem>
#include <string>

namespace hemiroll::game {

std::filesystem::path ghostFile(const std::filesystem::path& dataDir, const std::string& levelName,
                                const std::string& player);

// Copies `replay` over the ghost, atomically (a copy beside it, then a
// rename). "" when kept, else a sentence naming the file.
std::string keepAsGhost(const std::filesystem::path& replay, const std::filesystem::path& ghost);

}  // namespace hemiroll::game
