#pragma once
// Where a player's best run of a level is kept for racing: a replay log at
// <data dir>/ghosts/<player>/<level name>.hrr, replaced when the player
// beats it. The log carries the level's hash, so a ghost of an older version
// of the level is refused when loaded (ReplayPlayer), not raced.

#include <filesystem>
#include <optional>
#include <string>

namespace hemiroll::game {

std::filesystem::path ghostFile(const std::filesystem::path& dataDir, const std::string& levelName,
                                const std::string& player);

// Copies `replay` over the ghost, atomically (a copy beside it, then a
// rename), with the run's judged time [s] beside it (<ghost>.time: the log
// runs on a few ticks past the judge's end, until the screen stops the
// loop). "" when kept, else a sentence naming the file.
std::string keepAsGhost(const std::filesystem::path& replay, const std::filesystem::path& ghost, double time);

// The judged time kept with a ghost; nullopt when there is none or it is unreadable.
std::optional<double> ghostTime(const std::filesystem::path& ghost);

// Whose run a ghost is (issue 27: the autopilot's line was labelled "your
// best"), kept beside it in <ghost>.by: the player's own or the autopilot's.
enum class GhostOwner { Player, Autopilot };
// "" when kept, else a sentence naming the file.
std::string keepGhostOwner(const std::filesystem::path& ghost, GhostOwner owner);
// A ghost without a readable <ghost>.by (kept before there was one) is the
// player's: only their new bests became ghosts then, and "Race this line".
GhostOwner ghostOwner(const std::filesystem::path& ghost);

}  // namespace hemiroll::game
