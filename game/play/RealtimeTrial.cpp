#include "game/play/RealtimeTrial.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "engine/haptics/RecordRow.h"
#include "engine/haptics/ServoClock.h"
#include "engine/script/ScriptError.h"
#include "engine/script/TaskJudge.h"
#include "engine/script/TrialSummaryAccumulator.h"
#include "game/play/HandoffBotDevice.h"
#include "game/play/ObservationBuilder.h"

namespace hemiroll::game {

using script::TrialOutcome;

namespace {

physics::Vec3 vec(const std::array<double, 3>& t) { return {t[0], t[1], t[2]}; }

physics::ForceDrivenState stateOf(const std::array<double, 12>& a) {
  return Eigen::Map<const physics::ForceDrivenState>(a.data());
}

}  // namespace

TrialResult RealtimeTrial::run() {
  const auto wallStart = std::chrono::steady_clock::now();
  const script::LevelDef& def = level_.def;
  script::LevelScript& levelScript = *level_.script;

  auto ring = std::make_unique<haptics::RecordRing>();  // every tick, for the judge
  haptics::ServoLoopDef loopDef = HeadlessTrial::loopDefFor(def);
  loopDef.requestRealtime = true;
  loopDef.recordRing = ring.get();
  loopDef.recordEvery = 1;
  HandoffBotDevice device(HeadlessTrial::deviceSpec(), loopDef.mapping);
  haptics::ServoLoop loop(loopDef, device);
  script::TaskJudge judge(def.task);
  script::TrialSummaryAccumulator accumulator;
  const ObservationBuilder observer(def.params);
  TrialResult result;

  haptics::ServoSnapshot snapshot;
  snapshot.state = loopDef.initialState;
  script::BotObservation obs;
  script::TrialObservation levelView;
  levelView.state = stateOf(snapshot.state);
  double botTime = 0.0;  // simulation time of the last observation the bot answered

  // One bot call on the latest snapshot; false when the bot failed (the
  // trial is then finished).
  auto callBot = [&](double time) {
    observer.fill(time, stateOf(snapshot.state), snapshot, judge, obs);
    try {
      const script::BotAction a = bot_.act(obs);
      if (a.hasVelocity)
        device.publish(time, vec(a.position), vec(a.velocity));
      else
        device.publish(time, vec(a.position));
    } catch (const script::ScriptError& e) {
      judge.finish(TrialOutcome::Failure, std::string("bot error: ") + e.what(), time);
      levelScript.update(levelView, judge);  // on_fail
      return false;
    }
    botTime = time;
    return true;
  };

  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);
  try {
    bot_.init(HeadlessTrial::levelInfoFor(def, def.source), settings_.seed);
  } catch (const script::ScriptError& e) {
    judge.finish(TrialOutcome::Failure, std::string("bot error: ") + e.what(), 0.0);
  }
  levelScript.start(levelView, judge);
  if (judge.finished())
    levelScript.update(levelView, judge);  // on_fail for a failed init
  else
    callBot(0.0);  // a pose before the first tick

  long long judgedTicks = 0;
  if (!judge.finished()) {
    loop.start();
    haptics::SteadyServoClock clock;
    const auto botPeriod = static_cast<std::int64_t>(std::llround(1e9 / kBotRate));
    std::int64_t deadline = clock.now() + botPeriod;
    // A loop that stops ticking (it should not) must not hang the command.
    const double wallLimit = def.task.timeLimit * settings_.maxTimeFactor + 10.0;
    haptics::RecordRow row;
    long iterations = 0;
    while (!judge.finished()) {
      while (!judge.finished() && ring->pop(row)) {
        script::JudgeInput input;
        input.time = row.time;
        input.state = stateOf(row.state);
        input.event = row.event;
        judge.judge(input);
        script::EffortInput effort;
        effort.proxyPosition = vec(row.proxyPosition);
        effort.handForce = vec(row.handForce);
        accumulator.add(input, effort, judge);
        result.maxRenderedForce = std::max(result.maxRenderedForce, vec(row.renderedForce).norm());
        result.maxProxyDistance = std::max(result.maxProxyDistance, row.proxyDistance);
        if (!judge.finished() && row.fault != haptics::SafetyFault::None)
          judge.finish(TrialOutcome::Failure, std::string("safety: ") + haptics::safetyFaultName(row.fault), row.time);
        if (settings_.recordRing != nullptr && row.tick % static_cast<std::uint64_t>(settings_.recordEvery) == 0)
          settings_.recordRing->push(row);
        levelView.time = row.time;
        levelView.state = input.state;
        levelView.proxy = effort.proxyPosition;
        levelView.handForce = effort.handForce;
        levelScript.update(levelView, judge);
        judgedTicks = static_cast<long long>(row.tick);
        result.finalState = input.state;
      }
      // Every second: the recorder's ring (4096 rows) never fills between drains.
      if (settings_.drainRecording && ++iterations % static_cast<long>(kBotRate) == 0) settings_.drainRecording();
      if (judge.finished()) break;
      if (loop.recordDropped() > 0) {
        judge.finish(TrialOutcome::Failure, "the judge fell behind the servo loop (ticks dropped)", levelView.time);
        break;
      }
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count() > wallLimit) {
        judge.finish(TrialOutcome::Failure, "the servo loop stalled", levelView.time);
        break;
      }
      if (loop.latest(snapshot) && snapshot.time > botTime && !callBot(snapshot.time)) break;
      clock.waitUntil(deadline);
      deadline += botPeriod;
    }
    loop.stop();
  }
  if (settings_.drainRecording) settings_.drainRecording();

  result.outcome = judge.outcome();
  result.reason = std::string(judge.reason());
  result.time = judge.finishTime();
  result.ticks = judgedTicks;
  result.summary = accumulator.summary(judge);
  const script::ScoreResult score = levelScript.score(result.summary);
  result.score = score.score;
  result.medal = score.medal;
  result.scoreError = score.error;
  if (judgedTicks == 0) result.finalState = stateOf(loopDef.initialState);
  result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return result;
}

}  // namespace hemiroll::game
