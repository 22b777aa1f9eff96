#pragma once
// The built-in bot "autopilot" (`hemiroll run LEVEL --bot autopilot`): the
// planner of engine/autopilot behind the same interface as a Lua bot. It
// reads only what a bot reads (the observation and the level info) and gives
// only what a bot gives (a proxy pose and velocity); when the autopilot
// gives up, the trial fails with "autopilot: <why>".

#include <memory>
#include <string>

#include "engine/autopilot/Autopilot.h"
#include "engine/haptics/Guidance.h"
#include "engine/script/BotPolicy.h"

namespace hemiroll::game {

inline constexpr const char* kAutopilotBotName = "autopilot";

struct AutopilotBotOptions {
  double budget = 1.0;  // planning effort (AutopilotDef::budget)
  bool plannerThread = false;  // plan beside the trial's thread (real-time play)
  // The autopilot holds the proxy itself (a bot, watch mode); false for a
  // guide or a hint, whose plan another hand follows (AutopilotDef::handStiffens).
  bool holdsProxy = true;
  int plannerNice = 19;  // AutopilotDef::plannerNice
};

class AutopilotBot final : public script::BotPolicy {
 public:
  explicit AutopilotBot(const AutopilotBotOptions& options = {});
  ~AutopilotBot() override;

  const std::string& name() const override { return name_; }
  void init(const script::BotLevelInfo& info, std::int64_t seed) override;
  script::BotAction act(const script::BotObservation& obs) override;
  std::string giveUpReason() const override;

  // Null before init.
  const autopilot::Autopilot* autopilot() const { return autopilot_.get(); }
  // Another hand has taken the proxy over (watch mode, the player took over).
  void letGoOfProxy();

 private:
  AutopilotBotOptions options_;
  std::string name_ = kAutopilotBotName;
  std::unique_ptr<autopilot::Autopilot> autopilot_;
  autopilot::AutopilotInput input_;
};

// The current stage's bands as the autopilot reads them from `obs`.
autopilot::Goal goalOf(const script::BotObservation& obs);

// The autopilot's answer to `obs` as a plan for haptic guidance (or a hint):
// where it would put the proxy now. Not valid once it has given up.
haptics::GuideSample guideSampleOf(AutopilotBot& autopilot, const script::BotObservation& obs);

}  // namespace hemiroll::game
