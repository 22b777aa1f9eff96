#include "game/trial/HeadlessTrial.h"

#include <chrono>
#include <cmath>

#include "engine/physics/StateKinematics.h"
#include "engine/script/ScriptError.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/BotDevice.h"
#include "game/trial/ObservationBuilder.h"
#include "game/trial/RealtimeTrial.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

using script::TrialOutcome;

HeadlessTrial::HeadlessTrial(script::LoadedLevel& level, script::BotPolicy& bot, const TrialSettings& settings)
    : level_(level), bot_(bot), settings_(settings) {}

TrialResult HeadlessTrial::run() {
  if (settings_.realtime) return runRealtimeTrial(level_, bot_, settings_);
  const auto wallStart = std::chrono::steady_clock::now();
  const script::LevelDef& def = level_.def;

  haptics::ServoLoopDef loopDef = trialLoopDef(def);
  loopDef.recordRing = settings_.recordRing;
  loopDef.recordEvery = settings_.recordEvery;
  loopDef.guidance = settings_.guidance;
  BotDevice device(botDeviceSpec(), loopDef.mapping, loopDef.period);
  haptics::ServoLoop loop(loopDef, device);
  TrialJudge judging(level_);
  const ObservationBuilder observer(def.params, loopDef.mapping);
  const physics::ForceDrivenState initial = physics::forceStateOf(loopDef.initialState);

  haptics::ServoSnapshot snapshot;  // defaults until the first tick publishes
  snapshot.state = loopDef.initialState;
  script::BotObservation obs;

  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);

  // Headless: each script's time in Lua, and the autopilot's planning, are
  // bounded by multiples of the simulated time (TrialTiming.h).
  const script::TrialTiming timing;
  bot_.setTiming(timing);
  level_.script->setTiming(timing);
  try {
    bot_.init(botLevelInfo(def, def.source), settings_.seed);
  } catch (const script::ScriptError& e) {
    judging.judge().finish(TrialOutcome::Failure, std::string("bot error: ") + e.what(), loop.time());
  }
  judging.start(initial);  // on_start, and on_fail for a failed init

  std::unique_ptr<AutopilotBot> guide;
  if (settings_.guidance.active()) {
    AutopilotBotOptions guiding;
    guiding.holdsProxy = false;  // the bot's hand holds the proxy; the plan only guides it
    guide = std::make_unique<AutopilotBot>(guiding);
    guide->setTiming(timing);
    try {
      guide->init(botLevelInfo(def, def.source), settings_.seed);
    } catch (const script::ScriptError& e) {
      judging.fail(std::string("guidance: ") + e.what());
    }
  }

  const double period = loopDef.period;
  const auto maxTicks = static_cast<std::uint64_t>(std::ceil(def.task.timeLimit * settings_.maxTimeFactor / period)) + 1;

  while (!judging.finished() && loop.ticks() < maxTicks) {
    observer.fill(loop.time(), loop.state(), snapshot, judging.judge(), obs);
    script::BotAction action;
    try {
      action = bot_.act(obs);
    } catch (const script::ScriptError& e) {
      judging.fail(std::string("bot error: ") + e.what());
      break;
    }
    if (std::string why = bot_.giveUpReason(); !why.empty()) {
      judging.fail(why);
      break;
    }
    if (action.hasVelocity)
      device.setPose(physics::vec3Of(action.position), physics::vec3Of(action.velocity));
    else
      device.setPose(physics::vec3Of(action.position));
    if (guide) loop.publishGuide(guideSampleOf(*guide, obs));

    loop.tick();
    loop.latest(snapshot);
    judging.judgeTick(snapshot);
    if (settings_.drainRecording && snapshot.tick % kDrainEveryTicks == 0) settings_.drainRecording();
  }
  if (!judging.finished()) judging.fail("the trial did not end within its time limit");
  if (settings_.drainRecording) settings_.drainRecording();

  TrialResult result = judging.result(initial);
  result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return result;
}

}  // namespace hemiroll::game
