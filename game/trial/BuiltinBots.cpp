#include "game/trial/BuiltinBots.h"

#include "engine/script/BotScript.h"
#include "game/trial/PassiveHandBot.h"

namespace hemiroll::game {

bool isBuiltinBot(const std::string& name) { return name == kAutopilotBotName || name == kPassiveHandBotName; }

std::unique_ptr<script::BotPolicy> makeBot(const std::string& nameOrPath, std::uint64_t seed,
                                           const AutopilotBotOptions& autopilot) {
  if (nameOrPath == kAutopilotBotName) return std::make_unique<AutopilotBot>(autopilot);
  if (nameOrPath == kPassiveHandBotName) return std::make_unique<PassiveHandBot>();
  script::BotLoadOptions options;
  options.seed = seed;
  return std::make_unique<script::BotScript>(nameOrPath, options);
}

}  // namespace hemiroll::game
