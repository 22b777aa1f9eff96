#pragma once
// What `--bot NAME` means everywhere a bot plays (run, session, the game's
// watch mode): a built-in name ("autopilot", "passive-hand", "human") or the
// path of a Lua bot.

#include <cstdint>
#include <memory>
#include <string>

#include "engine/script/BotPolicy.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/HumanBot.h"

namespace hemiroll::game {

// The built-in bots' own settings (flags of run and session).
struct BuiltinBotOptions {
  AutopilotBotOptions autopilot;
  HumanBotOptions human;
};

bool isBuiltinBot(const std::string& name);

// Throws script::ScriptError for a Lua bot that does not load.
std::unique_ptr<script::BotPolicy> makeBot(const std::string& nameOrPath, std::uint64_t seed,
                                           const BuiltinBotOptions& options = {});

}  // namespace hemiroll::game
