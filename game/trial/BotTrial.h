#pragma once
// One trial of a level played by a bot, on a TrialRig (the same loop, judge
// and record tap a person's trial uses). Every bot call:
//   observation -> bot.act (Lua or the autopilot) -> the bot's device pose
//   -> ServoLoop::tick (device, coupling, physics, events, safety, ramp)
//   -> TrialJudge (TaskJudge, summary, level callbacks, safety faults)
// until the judge ends the trial; then the level's score function.
//
// The rig's two drivers:
//   stepping (the default: `hemiroll run`, sessions with --bot, tests): a
//     BotDevice, bot call and tick back to back on the calling thread with
//     no clock: as fast as the CPU allows and bit for bit the same for the
//     same level, bot and seed;
//   threaded (`realtime`, `hemiroll run --realtime`): the servo loop on its
//     own thread at 1 kHz (SCHED_FIFO when permitted) and the bot on the
//     calling thread at kRealtimeBotRate, never inside a tick: every bot
//     period the rig judges every tick the loop ran (none skipped), then the
//     bot answers the latest snapshot through a HandoffBotDevice (lock free,
//     extrapolated between answers). Not deterministic: the threads' timing
//     decides which pose each tick sees.
//
// With guidance, a second policy (the autopilot) answers every observation
// too; its answer moves nothing, it only becomes the loop's guide. An
// autopilot that gives up leaves the trial without guidance (the bot plays on).
//
// Ends early, as a failure with a reason, when the bot fails ("bot error:
// file:line: ...", from init or act), when it gives up ("autopilot: ..."),
// when a safety watchdog trips ("safety: <fault>"), when a level callback
// fails (the level runtime reports it), and in real time when the judge
// falls behind the loop or the loop stalls.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

#include "engine/haptics/Guidance.h"
#include "engine/script/BotObservation.h"
#include "engine/script/BotPolicy.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/TrialTiming.h"
#include "game/trial/ObservationBuilder.h"
#include "game/trial/TrialRig.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

class AutopilotBot;
class BotDevice;
class HandoffBotDevice;

inline constexpr double kRealtimeBotRate = 500.0;  // [Hz] bot calls beside a threaded loop

struct TrialSettings {
  std::uint64_t seed = 0;  // handed to the bot's init (the level was loaded with it)
  bool realtime = false;   // the threaded driver: servo thread at 1 kHz, bot beside it
  // Safety margin on the length of a trial: the judge ends it at the level's
  // time limit; this cap only guards against a level that never ends.
  double maxTimeFactor = 1.01;
  // Haptic guidance (engine/haptics/Guidance.h): when active, the trial runs
  // an autopilot beside the bot, on the same observations, and publishes its
  // plan to the loop every bot call; the device adds the guidance force.
  haptics::GuidanceDef guidance;
  // In a research session: the trial's place and the participant's memory,
  // handed to the bot's init (BotLevelInfo; the guide's autopilot gets neither).
  script::TrialPlace place;
  script::BotMemory* memory = nullptr;
  // The device the bot's hand is held to: a desk device (botDeviceSpec), or
  // a device profile's (DeviceProfiles.h: deviceSpecOf) with that profile's
  // safety limits (safetyOf; none: the loop's defaults).
  haptics::DeviceSpec device = botDeviceSpec();
  std::optional<haptics::SafetyDef> safety;
};

class BotTrial {
 public:
  // Builds the rig (throws std::invalid_argument for a level the loop
  // refuses). `level` and `bot` are used, not copied; both must outlive this.
  BotTrial(script::LoadedLevel& level, script::BotPolicy& bot, const TrialSettings& settings);
  ~BotTrial();
  BotTrial(const BotTrial&) = delete;
  BotTrial& operator=(const BotTrial&) = delete;

  // Its loop definition (for a recording's sidecar) and record tap, before run().
  TrialRig& rig() { return rig_; }

  // Plays the trial to its end, once.
  TrialResult run();

 private:
  void begin(const script::TrialTiming& timing);
  bool answer(double time, const physics::ForceDrivenState& state);
  void runStepping();
  void runThreaded();
  void paceBot();

  script::LoadedLevel& level_;
  script::BotPolicy& bot_;
  TrialSettings settings_;
  BotDevice* botDevice_ = nullptr;        // stepping: the rig's device
  HandoffBotDevice* handoff_ = nullptr;   // threaded: the rig's device
  TrialRig rig_;
  ObservationBuilder observer_;
  script::BotObservation obs_;
  std::unique_ptr<AutopilotBot> guide_;
  std::chrono::steady_clock::time_point wallStart_;
};

}  // namespace hemiroll::game
