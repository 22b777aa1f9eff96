#pragma once
// What plays a level in a trial: anything that, once per tick, turns the
// observation into a proxy pose. A Lua module (BotScript) is one; the
// built-in autopilot (game/trial/AutopilotBot) is another. The trial loops
// (game/trial/BotTrial, either driver) know only this interface.

#include <cstdint>
#include <string>

#include "engine/script/BotObservation.h"
#include "engine/script/TrialTiming.h"

namespace hemiroll::script {

struct BotAction {
  Triple3 position{};  // proxy, scene [m]
  Triple3 velocity{};  // proxy velocity, scene [m/s]; meaningful only when hasVelocity
  bool hasVelocity = false;
};

class BotPolicy {
 public:
  virtual ~BotPolicy() = default;
  virtual const std::string& name() const = 0;
  // Before init: how the trial runs, so that the policy can keep its own
  // computation within the trial's budgets (a Lua bot's time in Lua, the
  // autopilot's planning). A policy that ignores it has no budget.
  virtual void setTiming(const TrialTiming& /*timing*/) {}
  // Once per trial, before the first act. Throws ScriptError on failure.
  virtual void init(const BotLevelInfo& info, std::int64_t seed) = 0;
  // Once per tick. Throws ScriptError on failure.
  virtual BotAction act(const BotObservation& obs) = 0;
  // After the trial's last tick, in a research session: a bot that keeps
  // the participant's memory somewhere of its own (a Lua bot's table) hands
  // it back to BotLevelInfo::memory. Throws ScriptError for a memory that
  // breaks BotMemory's rules (the memory is then left as it was).
  virtual void endTrial() {}
  // Non-empty once the bot gives up on the task for a reason it can name
  // (the trial then fails with it); empty otherwise.
  virtual std::string giveUpReason() const { return {}; }
};

}  // namespace hemiroll::script
