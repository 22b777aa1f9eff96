#pragma once
// Where a research session's data goes, and the names in it:
//
//   <data root>/<experiment>/<participant>/<session>/
//     session.json                  the manifest (SessionManifest)
//     results.csv                   one row per finished trial
//     trial-001.csv, trial-001.json the trials' recordings (docs/RECORDING.md)
//     trial-002.csv.aborted-1 ...   an interrupted trial's files, moved aside
//     bot-memory.json               a bot's memory across trials (SessionBotMemory.h)
//
// The ids name folders, so they are 1 to 64 letters, digits, '-' or '_'
// (no '.', no '/': nothing can point outside the data root).

#include <filesystem>
#include <string>

namespace hemiroll::game {

// <dataDirectory()>/sessions: the game's data directory (HEMIROLL_DATA_DIR,
// XDG_DATA_HOME, ~/.local/share/hemiroll).
std::filesystem::path defaultSessionsRoot();

// "" when `id` may name a folder; else one sentence naming `what` ("participant").
std::string checkFolderId(const std::string& id, const char* what);

std::filesystem::path sessionFolder(const std::filesystem::path& dataRoot, const std::string& experiment,
                                    const std::string& participant, const std::string& session);

// "trial-001" for index 1 (at least three digits: the files sort in order).
std::string sessionTrialId(int index);

inline constexpr const char* kManifestFile = "session.json";

}  // namespace hemiroll::game
