// engine/script/LevelScript: callbacks at the level's rate with a read-only
// state view, the level API, errors ending the trial with their reason,
// scoring and medals.

#include "engine/script/LevelScript.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "engine/script/LevelLoader.h"
#include "engine/script/ScriptError.h"
#include "engine/task/TrialSummaryAccumulator.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

LoadedLevel load(const std::string& source, const SandboxLimits& limits = {}) {
  LevelLoadOptions options;
  options.limits = limits;
  return LevelLoader(options).loadSource(source, "lv.lua");
}

// Runs ticks of 1 ms at rest until `seconds` or the end of the trial.
void run(LoadedLevel& level, TaskJudge& judge, double seconds) {
  TrialObservation obs;
  const int ticks = static_cast<int>(seconds * 1000.0 + 0.5);
  for (int tick = 0; tick <= ticks && !judge.finished(); ++tick) {
    obs.time = tick * 0.001;
    JudgeInput in;
    in.time = obs.time;
    judge.judge(in);
    level.script->update(obs, judge);
  }
  if (judge.finished()) level.script->update(obs, judge);  // idempotent after the end
}

constexpr const char* kFarTarget = "task = { targets = { x_p = { value = 1, tol = 0.001 } }, time_limit = 10 },";

TEST(LevelScript, OnUpdateRunsAtTheLevelsRateInSimulatedTime) {
  LoadedLevel level = load(std::string("local n = 0\nreturn { name = 'r', ") + kFarTarget +
                           "callbacks = { rate = 20, on_update = function(s) n = n + 1; "
                           "if s.t >= 2 then hemiroll.fail('calls ' .. n) end end } }");
  TaskJudge judge(level.def.task);
  run(level, judge, 5.0);
  // 20 Hz from t = 0.05: the call at t = 2.0 is the 40th.
  EXPECT_EQ(judge.reason(), "level: calls 40");
  EXPECT_EQ(judge.outcome(), TrialOutcome::Failure);
  EXPECT_DOUBLE_EQ(judge.finishTime(), 2.0);
}

TEST(LevelScript, StartSuccessAndFailEachRunOnce) {
  LoadedLevel level = load(R"(
    return { name = 'c', task = { targets = { x_p = { value = 0, tol = 0.001 } }, hold = 0.5 },
      callbacks = {
        on_start = function(s) hemiroll.message('start ' .. s.stage .. '/' .. s.stage_count) end,
        on_success = function(s) hemiroll.message('won at ' .. s.t, 5) end,
        on_fail = function(s, reason) hemiroll.message('lost: ' .. reason) end } })");
  TaskJudge judge(level.def.task);
  run(level, judge, 2.0);
  EXPECT_EQ(judge.outcome(), TrialOutcome::Success);
  const auto messages = level.script->takeMessages();
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0].text, "start 1/1");
  EXPECT_EQ(messages[1].text, "won at 0.5");
  EXPECT_EQ(messages[1].duration, 5.0);
  EXPECT_EQ(messages[1].time, 0.5);
  EXPECT_TRUE(level.script->takeMessages().empty());
}

TEST(LevelScript, AMessageIsAHudLineNotAFile) {
  // 256 pending messages of any length once held gigabytes (issue 19): each
  // is cut to 512 bytes.
  LoadedLevel level = load(R"(
    return { name = 'm', task = { targets = { x_p = { value = 0, tol = 0.001 } }, hold = 0.5 },
      callbacks = { on_start = function(s) hemiroll.message(string.rep('x', 100000)) end } })");
  TaskJudge judge(level.def.task);
  run(level, judge, 0.1);
  const auto messages = level.script->takeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].text, std::string(512, 'x'));
}

// A level that fails on its 0.2 s time limit, with `onFail` as its on_fail body.
LoadedLevel timingOut(const std::string& onFail) {
  return load("return { name = 'f', task = { targets = { x_p = { value = 1, tol = 0.001 } }, time_limit = 0.2 },"
              "callbacks = { on_fail = function(s, reason) " + onFail + " end } }");
}

TEST(LevelScript, AnErrorInOnFailIsKeptNotDropped) {
  // The trial has ended (time limit): the outcome stands, and the error is
  // there for the caller to report (it was dropped; issue 19).
  LoadedLevel level = timingOut("error('on_fail broke')");
  TaskJudge judge(level.def.task);
  run(level, judge, 1.0);
  EXPECT_EQ(judge.reason(), trial_reason::kTimeLimit);
  EXPECT_THAT(level.script->endCallbackError(), ::testing::HasSubstr("on_fail broke"));
}

TEST(LevelScript, OnFailGetsTheReason) {
  LoadedLevel level = timingOut("hemiroll.message(reason)");
  TaskJudge judge(level.def.task);
  run(level, judge, 1.0);
  const auto messages = level.script->takeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0].text, trial_reason::kTimeLimit);
}

TEST(LevelScript, TheStateViewIsReadOnlyAndShowsTheState) {
  LoadedLevel level = load(std::string("return { name = 'v', ") + kFarTarget +
                           "callbacks = { on_update = function(s)\n"
                           "  assert(s.proxy_x == 0.25 and s.w_z == 3 and s.inside == false and s.time_limit == 10)\n"
                           "  assert(getmetatable(s) == false)\n"
                           "  s.x_p = 5\n"
                           "end } }");
  TaskJudge judge(level.def.task);
  TrialObservation obs;
  obs.proxy = physics::Vec3(0.25, 0, 0);
  obs.state[physics::force_slot::w_z] = 3.0;
  for (int tick = 0; tick <= 100 && !judge.finished(); ++tick) {
    obs.time = tick * 0.001;
    JudgeInput in;
    in.time = obs.time;
    judge.judge(in);
    level.script->update(obs, judge);
  }
  EXPECT_EQ(judge.outcome(), TrialOutcome::Failure);
  EXPECT_THAT(std::string(judge.reason()), StartsWith("script error: lv.lua:4: the state view is read-only"));
}

TEST(LevelScript, RuntimeErrorEndsTheTrialWithFileAndLine) {
  LoadedLevel level = load(std::string("return { name = 'e', ") + kFarTarget +
                           "callbacks = { on_update = function(s)\n local t = nil\n return t.x\n end,\n"
                           " on_fail = function(s, r) hemiroll.message('must not run') end } }");
  TaskJudge judge(level.def.task);
  run(level, judge, 1.0);
  EXPECT_EQ(judge.outcome(), TrialOutcome::Failure);
  EXPECT_THAT(std::string(judge.reason()), StartsWith("script error: lv.lua:3: attempt to index a nil value"));
  EXPECT_DOUBLE_EQ(judge.finishTime(), 0.05);  // the first on_update (20 Hz default)
  EXPECT_EQ(level.script->scriptError(), std::string(judge.reason()));
  EXPECT_TRUE(level.script->takeMessages().empty());  // on_fail is not trusted after a script error
}

TEST(LevelScript, QuotaExhaustionEndsTheTrial) {
  SandboxLimits limits;
  limits.callInstructionQuota = 100'000;
  LoadedLevel level = load(std::string("return { name = 'q', ") + kFarTarget +
                               "callbacks = { on_start = function(s)\n while true do end\n end } }",
                           limits);
  TaskJudge judge(level.def.task);
  run(level, judge, 1.0);
  EXPECT_EQ(judge.outcome(), TrialOutcome::Failure);
  EXPECT_THAT(std::string(judge.reason()), StartsWith("script error: lv.lua:2: instruction quota"));
  EXPECT_EQ(judge.finishTime(), 0.0);
}

TEST(LevelScript, SetTargetAndClearTargetChangeTheJudgedTask) {
  LoadedLevel level = load(R"(
    return { name = 'd', task = { targets = { x_p = { value = 1, tol = 0.001 } }, time_limit = 10 },
      callbacks = { on_update = function(s)
        if s.t < 0.2 then return end
        hemiroll.set_target('p', {0, 0}, 0.002)
        hemiroll.clear_target('y_p')
      end } })");
  TaskJudge judge(level.def.task);
  run(level, judge, 1.0);
  // At 0.2 s x_p moved to 0 (where the state is) and y_p was added then dropped.
  EXPECT_EQ(judge.outcome(), TrialOutcome::Success);
  EXPECT_DOUBLE_EQ(judge.finishTime(), 0.201);  // judged on the tick after the change
  ASSERT_EQ(judge.components().size(), 1u);
  EXPECT_EQ(judge.components()[0].variable, TaskVariable::x_p);
  EXPECT_EQ(judge.components()[0].tolerance, 0.002);
}

TEST(LevelScript, BadApiCallsAreScriptErrors) {
  for (const char* call : {"hemiroll.set_target('q_p', 0, 1)", "hemiroll.set_target('p', {0}, 1)",
                           "hemiroll.set_target('x_p', 0, -1)", "hemiroll.fail()", "hemiroll.message('m', -2)"}) {
    LoadedLevel level = load(std::string("return { name = 'b', ") + kFarTarget +
                             "callbacks = { on_start = function(s)\n " + call + "\n end } }");
    TaskJudge judge(level.def.task);
    run(level, judge, 0.1);
    EXPECT_THAT(std::string(judge.reason()), StartsWith("script error: lv.lua:2: ")) << call;
  }
}

TEST(LevelScript, TheApiIsOnlyForCallbacks) {
  try {
    load("hemiroll.message('too early')\nreturn { name = 'x' }");
    FAIL() << "expected a ScriptError";
  } catch (const ScriptError& e) {
    EXPECT_THAT(e.what(), StartsWith("lv.lua:1: hemiroll.message is only available inside a level callback"));
  }
}

TEST(LevelScript, SucceedEndsTheTrialAndStageIsOneBased) {
  LoadedLevel level = load(std::string("return { name = 's', ") + kFarTarget +
                           "callbacks = { on_update = function(s) if hemiroll.stage() == 1 then "
                           "hemiroll.succeed('custom rule') end end } }");
  TaskJudge judge(level.def.task);
  run(level, judge, 1.0);
  EXPECT_EQ(judge.outcome(), TrialOutcome::Success);
  EXPECT_EQ(judge.reason(), "level: custom rule");
}

TEST(LevelScript, UpdatesDoNotGrowMemory) {
  LoadedLevel level = load(std::string("return { name = 'm', ") + kFarTarget +
                           "callbacks = { rate = 100, on_update = function(s) local x = s.x_p + s.t end } }");
  TaskJudge judge(level.def.task);
  run(level, judge, 1.0);  // warm up: every field and string exists now
  const std::size_t before = level.script->sandbox().memoryInUse();
  run(level, judge, 5.0);
  // The view is refreshed in place: numbers into existing slots. Allow 4 KiB
  // for the collector's timing, far below 500 calls x ~30 fields x 40 bytes.
  EXPECT_LE(level.script->sandbox().memoryInUse(), before + 4096);
  EXPECT_GE(level.script->callbackCalls(), 500);
}

TrialSummary summaryWithTime(double time, bool success) {
  TrialSummary s;
  s.time = time;
  s.outcome = success ? TrialOutcome::Success : TrialOutcome::Failure;
  return s;
}

TEST(LevelScript, ScoreAndMedalsFollowTheThresholds) {
  LoadedLevel level = load(R"(
    return { name = 'sc', score = function(s) if not s.success then return -1 end return 100 - s.time end,
             medals = { bronze = 10, silver = 50, gold = 90 } })");
  const struct { double time; Medal medal; } cases[] = {
      {5.0, Medal::Gold}, {10.0, Medal::Gold}, {10.5, Medal::Silver}, {50.0, Medal::Silver},
      {50.5, Medal::Bronze}, {90.0, Medal::Bronze}, {95.0, Medal::None}};
  for (const auto& c : cases) {
    const ScoreResult r = level.script->score(summaryWithTime(c.time, true));
    ASSERT_TRUE(r.score.has_value());
    EXPECT_EQ(*r.score, 100 - c.time);
    EXPECT_EQ(r.medal, c.medal) << c.time;
  }
  EXPECT_EQ(*level.script->score(summaryWithTime(1.0, false)).score, -1.0);
}

TEST(LevelScript, ScoreSeesEverySummaryField) {
  LoadedLevel level = load(R"(
    return { name = 'f', score = function(s)
      return s.time + s.ticks + s.stages_passed + s.stage_count + s.contact_path + s.point_path + s.effort
           + s.smoothness + s.best_margin + s.final_margin + s.final_components.x_p.margin + (s.reason == 'r' and 1000 or 0)
    end })");
  TrialSummary s;
  s.reason = "r";
  s.time = 1;
  s.ticks = 2;
  s.stagesPassed = 3;
  s.stageCount = 4;
  s.contactPath = 5;
  s.pointPath = 6;
  s.effort = 7;
  s.smoothness = 8;
  s.bestMargin = 9;
  s.finalMargin = 10;
  ComponentStatus c;
  c.variable = TaskVariable::x_p;
  c.margin = 11;
  s.finalComponents.push_back(c);
  EXPECT_EQ(*level.script->score(s).score, 1066.0);
}

TEST(LevelScript, ABrokenScoreIsReportedNotThrown) {
  LoadedLevel bad = load("return { name = 'b', score = function(s)\n return s.nothing.x\n end }");
  const ScoreResult r = bad.script->score(TrialSummary{});
  EXPECT_FALSE(r.score.has_value());
  EXPECT_THAT(r.error, StartsWith("script error: lv.lua:2: attempt to index a nil value"));
  LoadedLevel nan = load("return { name = 'n', score = function(s) return 0/0 end }");
  EXPECT_THAT(nan.script->score(TrialSummary{}).error, HasSubstr("must return a finite number, got nan"));
  LoadedLevel none = load("return { name = 'z' }");
  EXPECT_FALSE(none.script->score(TrialSummary{}).score.has_value());
  EXPECT_EQ(none.script->score(TrialSummary{}).error, "");
}

}  // namespace
}  // namespace hemiroll::script
