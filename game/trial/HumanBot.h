#pragma once
// The built-in bot "human" (`--bot human`): engine/human's simulated person,
// playing through what the screen shows. Each tick it builds the player's
// view from the observation (ScreenViewOf), adds the game's aids when they
// are on (the hint from HintCoach, the force cue), and hands the view and
// the force the device renders to the model, which answers with where its
// hand holds the proxy.

#include <memory>
#include <optional>
#include <string>

#include "engine/haptics/HandSpring.h"
#include "engine/human/HumanModel.h"
#include "engine/human/Practice.h"
#include "engine/script/BotPolicy.h"

namespace hemiroll::game {

inline constexpr const char* kHumanBotName = "human";

class HintCoach;

struct HumanBotOptions {
  human::HumanDef human;
  human::TechniqueDef technique;
  // The game's aids, as a player has them: the hint at a person's bandwidth
  // and the force cue.
  bool aids = false;
  // In a session (a memory to keep), the person learns: each trial's motor
  // noise follows the law of practice from `practice.noviceNoise` down to
  // `human.noise` (engine/human/Practice.h), counting the trials practised
  // in the memory's "practice_trials". Outside a session nothing is learnt.
  bool learns = true;
  human::PracticeDef practice;
  // On the mouse-hand device (human.device MouseHand): the game's simulated
  // hand between the person's mouse and the proxy (MouseDevice's hand feel).
  haptics::HandSpringDef mouseHand;
};

// The memory entries the human model keeps (script::BotMemory).
inline constexpr const char* kPracticeTrials = "practice_trials";  // trials played before
inline constexpr const char* kMotorNoise = "motor_noise";          // the noise of the latest trial

class HumanBot final : public script::BotPolicy {
 public:
  explicit HumanBot(const HumanBotOptions& options = {});
  ~HumanBot() override;

  const std::string& name() const override { return name_; }
  void init(const script::BotLevelInfo& info, std::int64_t seed) override;
  script::BotAction act(const script::BotObservation& obs) override;
  std::string giveUpReason() const override;

  // Null before init.
  const human::HumanModel* model() const { return model_ ? &*model_ : nullptr; }

 private:
  HumanBotOptions options_;
  std::string name_ = kHumanBotName;
  double radius_ = 0.04;
  std::optional<human::HumanModel> model_;
  std::unique_ptr<HintCoach> coach_;
  bool holding_ = false;
  // MouseHand: the simulated hand the person's mouse pulls (scene frame).
  std::optional<haptics::HandSpring> mouseHand_;
  double tick_ = 0.001;  // [s]
};

// What the screen shows a player of this observation (without the aids).
human::ScreenView screenViewOf(const script::BotObservation& obs);

}  // namespace hemiroll::game
