#include "game/trial/BuiltinBots.h"

#include "engine/script/BotScript.h"
#include "game/trial/PassiveHandBot.h"

namespace hemiroll::game {

bool isBuiltinBot(const std::string& name) {
  return name == kAutopilotBotName || name == kPassiveHandBotName || name == kHumanBotName;
}

std::unique_ptr<script::BotPolicy> makeBot(const std::string& nameOrPath, std::uint64_t seed,
                                           const BuiltinBotOptions& options) {
  if (nameOrPath == kAutopilotBotName) return std::make_unique<AutopilotBot>(options.autopilot);
  if (nameOrPath == kPassiveHandBotName) return std::make_unique<PassiveHandBot>();
  if (nameOrPath == kHumanBotName) return std::make_unique<HumanBot>(options.human);
  script::BotLoadOptions loadOptions;
  loadOptions.seed = seed;
  return std::make_unique<script::BotScript>(nameOrPath, loadOptions);
}

}  // namespace hemiroll::game
