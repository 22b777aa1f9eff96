#pragma once
// bot-memory.json in a session folder: the simulated participant's memory
// (script::BotMemory) after the last finished trial, so that a resumed
// session restores it. Written atomically after each trial, before its
// results row, with the memory before that trial beside it: a crash between
// the two leaves the trial to run again, and it runs again from the memory
// it started with.
//
//   {"format": "hemiroll-bot-memory", "format_version": 1, "after_trial": 5,
//    "memory": {"practice_trials": 5, ...}, "before": {"practice_trials": 4, ...}}

#include <filesystem>
#include <string>

#include "engine/script/BotMemory.h"

namespace hemiroll::game {

inline constexpr const char* kBotMemoryFile = "bot-memory.json";

// Throws SessionError (Environment) when it cannot be written.
void writeBotMemory(const std::filesystem::path& folder, int afterTrial, const script::BotMemory& after,
                    const script::BotMemory& before);

// The memory to start trial `done` + 1 with: empty for a new session (or
// one begun before memories were kept; `note` then says so). Throws
// SessionError (Environment) for a file that does not read or does not
// match the trials done (changed by hand).
script::BotMemory restoreBotMemory(const std::filesystem::path& folder, int done, std::string& note);

}  // namespace hemiroll::game
