#pragma once
// `hemiroll run --realtime`: the trial of HeadlessTrial with the servo loop
// on its own thread at 1 kHz (ServoLoop::start: SCHED_FIFO when permitted)
// and the bot on the calling thread at kRealtimeBotRate, never inside a tick:
//   servo thread:  device (HandoffBotDevice, extrapolating the bot's latest
//                  pose) -> coupling -> physics -> safety -> snapshot, and a
//                  RecordRow of every tick into a lock-free ring;
//   this thread:   every bot period, judge every tick the ring holds
//                  (TaskJudge, summary, level callbacks: no tick is skipped),
//                  then observe the latest snapshot, call the bot, publish
//                  its pose through the TripleBuffer hand-over.
// Not deterministic (the threads' timing decides which pose each tick sees);
// headless runs are the reproducible ones.

#include "game/trial/HeadlessTrial.h"

namespace hemiroll::game {

inline constexpr double kRealtimeBotRate = 500.0;  // [Hz] bot calls on the calling thread

// `level` and `bot` must outlive the call; settings.realtime is implied.
TrialResult runRealtimeTrial(script::LoadedLevel& level, script::BotPolicy& bot, const TrialSettings& settings);

}  // namespace hemiroll::game
