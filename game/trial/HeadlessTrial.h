#pragma once
// One trial of a level played by a bot, with the tick code of real-time play:
// every tick
//   observation -> bot.act (Lua or the autopilot) -> BotDevice pose
//   -> ServoLoop::tick (device, coupling, physics, events, safety, ramp)
//   -> TrialJudge (TaskJudge, summary, level callbacks, safety faults)
// until the judge ends the trial; then the level's score function.
//
// Headless (the default) runs ticks back to back on the calling thread with
// no clock: as fast as the CPU allows and bit-for-bit deterministic for the
// same level, bot and seed. `realtime` hands the trial to runRealtimeTrial: the
// servo loop on its own thread at 1 kHz, the bot on this thread at 500 Hz
// with a lock-free hand-over (no Lua in the servo thread).
//
// With guidance, a second policy (the autopilot) answers every observation
// too; its answer moves nothing, it only becomes the loop's guide. An
// autopilot that gives up leaves the trial without guidance (the bot plays on).
//
// Ends early, as a failure with a reason, when the bot fails ("bot error:
// file:line: ...", from init or act), when it gives up ("autopilot: ..."),
// when a safety watchdog trips ("safety: <fault>"), or when a level callback
// fails (the level runtime reports it).

#include <cstdint>
#include <functional>

#include "engine/haptics/Guidance.h"
#include "engine/haptics/RecordRow.h"
#include "engine/script/BotPolicy.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/TrialJudge.h"

namespace hemiroll::game {

struct TrialSettings {
  std::uint64_t seed = 0;    // handed to the bot's init (the level was loaded with it)
  bool realtime = false;     // servo thread at 1 kHz, bot beside it (runRealtimeTrial)
  // Safety margin on the length of a trial: the judge ends it at the level's
  // time limit; this cap only guards against a level that never ends.
  double maxTimeFactor = 1.01;
  // Recording (engine/record, through the servo loop's ring): the loop
  // pushes a row every recordEvery ticks into recordRing, and the trial calls
  // drainRecording every kDrainEveryTicks ticks and once at the end.
  haptics::RecordRing* recordRing = nullptr;
  int recordEvery = 10;
  std::function<void()> drainRecording;
  // Haptic guidance (engine/haptics/Guidance.h): when active, the trial runs
  // an autopilot beside the bot, on the same observations, and publishes its
  // plan to the loop every tick; the device adds the guidance force.
  haptics::GuidanceDef guidance;
};

class HeadlessTrial {
 public:
  // 1 s at 1 kHz: the ring (4096 rows) never fills between drains.
  static constexpr std::uint64_t kDrainEveryTicks = 1000;

  // `level` and `bot` are used, not copied; both must outlive run().
  HeadlessTrial(script::LoadedLevel& level, script::BotPolicy& bot, const TrialSettings& settings);

  TrialResult run();

 private:
  script::LoadedLevel& level_;
  script::BotPolicy& bot_;
  TrialSettings settings_;
};

}  // namespace hemiroll::game
