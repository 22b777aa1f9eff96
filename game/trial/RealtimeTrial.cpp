#include "game/trial/RealtimeTrial.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "engine/haptics/RecordRow.h"
#include "engine/haptics/ServoClock.h"
#include "engine/physics/StateKinematics.h"
#include "engine/script/ScriptError.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/HandoffBotDevice.h"
#include "game/trial/ObservationBuilder.h"
#include "game/trial/TrialJudge.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

using script::TrialOutcome;

TrialResult runRealtimeTrial(script::LoadedLevel& level, script::BotPolicy& bot, const TrialSettings& settings) {
  const auto wallStart = std::chrono::steady_clock::now();
  const script::LevelDef& def = level.def;

  auto ring = std::make_unique<haptics::RecordRing>();  // every tick, for the judge
  haptics::ServoLoopDef loopDef = trialLoopDef(def);
  loopDef.requestRealtime = true;
  loopDef.recordRing = ring.get();
  loopDef.recordEvery = 1;
  loopDef.guidance = settings.guidance;
  HandoffBotDevice device(botDeviceSpec(), loopDef.mapping);
  haptics::ServoLoop loop(loopDef, device);
  TrialJudge judging(level, settings.recordRing, settings.recordEvery);
  script::TaskJudge& judge = judging.judge();
  const ObservationBuilder observer(def.params, loopDef.mapping);
  const physics::ForceDrivenState initial = physics::forceStateOf(loopDef.initialState);

  haptics::ServoSnapshot snapshot;
  snapshot.state = loopDef.initialState;
  script::BotObservation obs;
  // Every call a tick makes (the bot's act, the level's on_update) has the
  // bot's period as its CPU deadline.
  const script::TrialTiming timing{.realtime = true, .tickSeconds = 1.0 / kRealtimeBotRate};
  bot.setTiming(timing);
  level.script->setTiming(timing);
  // Guidance: the autopilot answers the same observations (HeadlessTrial.h),
  // planning on its own thread as a real-time autopilot bot does.
  std::unique_ptr<AutopilotBot> guide;
  if (settings.guidance.active()) {
    AutopilotBotOptions options;
    options.plannerThread = true;
    options.holdsProxy = false;  // the bot's hand holds the proxy; the plan only guides it
    guide = std::make_unique<AutopilotBot>(options);
    guide->setTiming(timing);
    try {
      guide->init(botLevelInfo(def, def.source), static_cast<std::int64_t>(settings.seed));
    } catch (const script::ScriptError& e) {
      guide.reset();
      judge.finish(TrialOutcome::Failure, std::string("guidance: ") + e.what(), 0.0);  // on_fail at start
    }
  }
  double botTime = 0.0;  // simulation time of the last observation the bot answered

  // One bot call on the latest snapshot; false when the bot failed (the
  // trial is then finished).
  auto callBot = [&](double time) {
    observer.fill(time, physics::forceStateOf(snapshot.state), snapshot, judge, obs);
    try {
      const script::BotAction a = bot.act(obs);
      if (std::string why = bot.giveUpReason(); !why.empty()) {
        judging.fail(why);
        return false;
      }
      if (a.hasVelocity)
        device.publish(time, physics::vec3Of(a.position), physics::vec3Of(a.velocity));
      else
        device.publish(time, physics::vec3Of(a.position));
      if (guide) loop.publishGuide(guideSampleOf(*guide, obs));
    } catch (const script::ScriptError& e) {
      judging.fail(std::string("bot error: ") + e.what());
      return false;
    }
    botTime = time;
    return true;
  };

  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);
  std::string initError;
  try {
    bot.init(botLevelInfo(def, def.source), settings.seed);
  } catch (const script::ScriptError& e) {
    initError = std::string("bot error: ") + e.what();
    judge.finish(TrialOutcome::Failure, initError, 0.0);
  }
  judging.start(initial);  // on_start, and on_fail for a failed init
  if (!judge.finished()) callBot(0.0);  // a pose before the first tick

  if (!judge.finished()) {
    loop.start();
    haptics::SteadyServoClock clock;
    const auto botPeriod = static_cast<std::int64_t>(std::llround(1e9 / kRealtimeBotRate));
    std::int64_t deadline = clock.now() + botPeriod;
    // A loop that stops ticking (it should not) must not hang the command.
    const double wallLimit = def.task.timeLimit * settings.maxTimeFactor + 10.0;
    long iterations = 0;
    while (!judge.finished()) {
      judging.drain(*ring);
      // Every second: the recorder's ring (4096 rows) never fills between drains.
      if (settings.drainRecording && ++iterations % static_cast<long>(kRealtimeBotRate) == 0) settings.drainRecording();
      if (judge.finished()) break;
      if (loop.recordDropped() > 0) {
        judging.fail("the judge fell behind the servo loop (ticks dropped)");
        break;
      }
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count() > wallLimit) {
        judging.fail("the servo loop stalled");
        break;
      }
      if (loop.latest(snapshot) && snapshot.time > botTime && !callBot(snapshot.time)) break;
      clock.waitUntil(deadline);
      deadline += botPeriod;
    }
    loop.stop();
  }
  if (settings.drainRecording) settings.drainRecording();

  TrialResult result = judging.result(initial);
  result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return result;
}

}  // namespace hemiroll::game
