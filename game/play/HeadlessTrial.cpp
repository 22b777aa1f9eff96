#include "game/play/HeadlessTrial.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/script/ScriptError.h"
#include "engine/script/TaskJudge.h"
#include "engine/script/TrialSummaryAccumulator.h"
#include "game/play/BotDevice.h"
#include "game/play/ObservationBuilder.h"
#include "game/play/RealtimeTrial.h"

namespace hemiroll::game {

using script::TrialOutcome;

namespace {

physics::Vec3 vec(const haptics::Triple& t) { return {t[0], t[1], t[2]}; }

}  // namespace

HeadlessTrial::HeadlessTrial(script::LoadedLevel& level, script::BotPolicy& bot, const TrialSettings& settings)
    : level_(level), bot_(bot), settings_(settings) {}

haptics::DeviceSpec HeadlessTrial::deviceSpec() {
  haptics::DeviceSpec spec;  // a desk device's limits (DeviceSpec defaults): the bot is held to them
  spec.name = "bot";
  return spec;
}

haptics::ServoLoopDef HeadlessTrial::loopDefFor(const script::LevelDef& level, const std::string& device) {
  haptics::ServoLoopDef def;
  def.requestRealtime = false;  // the loop's own thread is not used here
  def.params = level.params;
  def.coupling = level.coupling;
  const script::DeviceMappingDef& mapping = level.mappingFor(device);
  def.mapping.scale = mapping.scale;
  def.mapping.offset = physics::Vec3(mapping.offset[0], mapping.offset[1], mapping.offset[2]);
  for (int i = 0; i < 12; ++i) def.initialState[static_cast<std::size_t>(i)] = level.initial[i];
  return def;
}

script::BotLevelInfo HeadlessTrial::levelInfoFor(const script::LevelDef& level, const std::string& file) {
  const haptics::ServoLoopDef def = loopDefFor(level);
  script::BotLevelInfo info;
  info.name = level.name;
  info.file = file;
  info.radius = level.params.radius;
  info.shellMass = level.params.shellMass;
  info.pointMass = level.params.pointMass;
  info.gravity = level.params.gravity;
  info.method = level.coupling.visualOnly ? "visual" : physics::forceMethodName(level.coupling.method);
  info.stiffness = level.coupling.stiffness;
  info.damping = level.coupling.damping;
  info.alpha = level.coupling.alpha;
  info.dt = def.period;
  info.timeLimit = level.task.timeLimit;
  info.engageDistance = def.safety.engagement.engageDistance;
  info.workspaceRadius = deviceSpec().workspaceRadius * def.mapping.scale;
  info.workspaceCentre = {def.mapping.offset.x(), def.mapping.offset.y(), def.mapping.offset.z()};
  return info;
}

TrialResult HeadlessTrial::run() {
  if (settings_.realtime) return RealtimeTrial(level_, bot_, settings_).run();
  const auto wallStart = std::chrono::steady_clock::now();
  const script::LevelDef& def = level_.def;
  script::LevelScript& levelScript = *level_.script;

  haptics::ServoLoopDef loopDef = loopDefFor(def);
  loopDef.recordRing = settings_.recordRing;
  loopDef.recordEvery = settings_.recordEvery;
  BotDevice device(deviceSpec(), loopDef.mapping, loopDef.period);
  haptics::ServoLoop loop(loopDef, device);
  script::TaskJudge judge(def.task);
  script::TrialSummaryAccumulator accumulator;
  const ObservationBuilder observer(def.params);

  haptics::ServoSnapshot snapshot;  // defaults until the first tick publishes
  snapshot.state = loopDef.initialState;
  script::BotObservation obs;
  script::TrialObservation levelView;
  levelView.state = loop.state();
  TrialResult result;

  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);

  try {
    bot_.init(levelInfoFor(def, def.source), settings_.seed);
  } catch (const script::ScriptError& e) {
    judge.finish(TrialOutcome::Failure, std::string("bot error: ") + e.what(), loop.time());
  }
  levelScript.start(levelView, judge);
  if (judge.finished()) levelScript.update(levelView, judge);  // on_fail for a failed init

  const double period = loopDef.period;
  const auto maxTicks = static_cast<std::uint64_t>(std::ceil(def.task.timeLimit * settings_.maxTimeFactor / period)) + 1;

  while (!judge.finished() && loop.ticks() < maxTicks) {
    observer.fill(loop.time(), loop.state(), snapshot, judge, obs);
    script::BotAction action;
    try {
      action = bot_.act(obs);
    } catch (const script::ScriptError& e) {
      judge.finish(TrialOutcome::Failure, std::string("bot error: ") + e.what(), loop.time());
      levelScript.update(levelView, judge);  // on_fail
      break;
    }
    if (std::string why = bot_.giveUpReason(); !why.empty()) {
      judge.finish(TrialOutcome::Failure, why, loop.time());
      levelScript.update(levelView, judge);  // on_fail
      break;
    }
    if (action.hasVelocity)
      device.setPose(vec(action.position), vec(action.velocity));
    else
      device.setPose(vec(action.position));

    loop.tick();
    loop.latest(snapshot);

    script::JudgeInput input;
    input.time = snapshot.time;
    input.state = loop.state();
    input.event = snapshot.event;
    judge.judge(input);
    script::EffortInput effort;
    effort.proxyPosition = vec(snapshot.proxyPosition);
    effort.handForce = vec(snapshot.handForce);
    accumulator.add(input, effort, judge);
    result.maxRenderedForce = std::max(result.maxRenderedForce, vec(snapshot.renderedForce).norm());
    result.maxProxyDistance = std::max(result.maxProxyDistance, snapshot.proxyDistance);
    if (!judge.finished() && snapshot.fault != haptics::SafetyFault::None)
      judge.finish(TrialOutcome::Failure, std::string("safety: ") + haptics::safetyFaultName(snapshot.fault),
                   snapshot.time);
    if (settings_.drainRecording && snapshot.tick % kDrainEveryTicks == 0) settings_.drainRecording();

    levelView.time = snapshot.time;
    levelView.state = input.state;
    levelView.proxy = effort.proxyPosition;
    levelView.handForce = effort.handForce;
    levelScript.update(levelView, judge);
  }
  if (!judge.finished()) {
    judge.finish(TrialOutcome::Failure, "the trial did not end within its time limit", loop.time());
    levelScript.update(levelView, judge);
  }
  if (settings_.drainRecording) settings_.drainRecording();

  result.outcome = judge.outcome();
  result.reason = std::string(judge.reason());
  result.time = judge.finishTime();
  result.ticks = static_cast<long long>(loop.ticks());
  result.summary = accumulator.summary(judge);
  const script::ScoreResult score = levelScript.score(result.summary);
  result.score = score.score;
  result.medal = score.medal;
  result.scoreError = score.error;
  result.finalState = loop.state();
  result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return result;
}

}  // namespace hemiroll::game
