#include "engine/script/LevelScript.h"

#include <lua.hpp>

#include <algorithm>
#include <cmath>

#include "engine/script/LevelScriptApi.h"
#include "engine/script/LuaTableReader.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::script {

namespace {

constexpr const char* kViewFields[] = {"x_p", "y_p", "xd_p", "yd_p", "w_x", "w_y", "w_z", "u_a", "v_a", "u_o", "v_o", "psi"};

// __newindex of the state view: the view is read-only.
int refuseWrite(lua_State* L) { return luaL_error(L, "the state view is read-only"); }

void setNumber(lua_State* L, int table, const char* key, double value) {
  lua_pushnumber(L, value);
  lua_setfield(L, table, key);
}

}  // namespace

LevelScript::LevelScript(std::shared_ptr<LuaSandbox> sandbox, const LevelDef& def)
    : sandbox_(std::move(sandbox)), def_(def) {
  lua_State* L = sandbox_->state();
  lua_checkstack(L, 4);
  const int level = lua_gettop(L);
  const auto reference = [&](const char* table, const char* key, bool present) {
    if (!present) return LUA_NOREF;
    if (table != nullptr) lua_getfield(L, level, table);
    lua_getfield(L, table != nullptr ? -1 : level, key);
    const int ref = luaL_ref(L, LUA_REGISTRYINDEX);
    if (table != nullptr) lua_pop(L, 1);
    return ref;
  };
  onStartRef_ = reference("callbacks", "on_start", def_.callbacks.onStart);
  onUpdateRef_ = reference("callbacks", "on_update", def_.callbacks.onUpdate);
  onSuccessRef_ = reference("callbacks", "on_success", def_.callbacks.onSuccess);
  onFailRef_ = reference("callbacks", "on_fail", def_.callbacks.onFail);
  scoreRef_ = reference(nullptr, "score", def_.scoring.hasScoreFunction);
  levelRef_ = luaL_ref(L, LUA_REGISTRYINDEX);  // pops the level table
  whereStart_ = def_.source + ": callbacks.on_start";
  whereUpdate_ = def_.source + ": callbacks.on_update";
  whereSuccess_ = def_.source + ": callbacks.on_success";
  whereFail_ = def_.source + ": callbacks.on_fail";
  whereScore_ = def_.source + ": score";
  period_ = 1.0 / def_.callbacks.rate;
  messages_.reserve(16);
  lua_pushlightuserdata(L, this);
  lua_setfield(L, LUA_REGISTRYINDEX, LevelScriptApi::kRegistryKey);
  buildView();
}

LevelScript::~LevelScript() {
  lua_State* L = sandbox_->state();
  lua_pushnil(L);
  lua_setfield(L, LUA_REGISTRYINDEX, LevelScriptApi::kRegistryKey);
  for (int ref : {levelRef_, onStartRef_, onUpdateRef_, onSuccessRef_, onFailRef_, scoreRef_, viewRef_, viewDataRef_})
    luaL_unref(L, LUA_REGISTRYINDEX, ref);
}

void LevelScript::buildView() {
  lua_State* L = sandbox_->state();
  lua_createtable(L, 0, 32);  // data
  lua_pushvalue(L, -1);
  viewDataRef_ = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_newtable(L);  // the view: empty, reads go to data through __index
  lua_createtable(L, 0, 3);
  lua_pushvalue(L, -3);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, refuseWrite);
  lua_setfield(L, -2, "__newindex");
  lua_pushboolean(L, 0);
  lua_setfield(L, -2, "__metatable");  // getmetatable(view) is false: data stays out of reach
  lua_setmetatable(L, -2);
  viewRef_ = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_pop(L, 1);
}

void LevelScript::refreshView(const TrialObservation& obs, const TaskJudge& judge) {
  lua_State* L = sandbox_->state();
  lua_checkstack(L, 3);
  lua_rawgeti(L, LUA_REGISTRYINDEX, viewDataRef_);
  const int data = lua_gettop(L);
  setNumber(L, data, "t", obs.time);
  for (int i = 0; i < 12; ++i) setNumber(L, data, kViewFields[i], obs.state[i]);
  using namespace physics::force_slot;
  setNumber(L, data, "omega_norm", std::sqrt(obs.state[w_x] * obs.state[w_x] + obs.state[w_y] * obs.state[w_y] + obs.state[w_z] * obs.state[w_z]));
  setNumber(L, data, "proxy_x", obs.proxy.x());
  setNumber(L, data, "proxy_y", obs.proxy.y());
  setNumber(L, data, "proxy_z", obs.proxy.z());
  setNumber(L, data, "force_x", obs.handForce.x());
  setNumber(L, data, "force_y", obs.handForce.y());
  setNumber(L, data, "force_z", obs.handForce.z());
  lua_pushinteger(L, std::min(judge.stage(), std::max(judge.stageCount() - 1, 0)) + 1);
  lua_setfield(L, data, "stage");
  lua_pushinteger(L, judge.stageCount());
  lua_setfield(L, data, "stage_count");
  setNumber(L, data, "held", judge.holdTime());
  setNumber(L, data, "hold", judge.requiredHold());
  lua_pushboolean(L, judge.allInside());
  lua_setfield(L, data, "inside");
  const double margin = judge.worstNormalizedMargin();
  setNumber(L, data, "margin", std::isfinite(margin) ? margin : 1.0);
  setNumber(L, data, "time_limit", judge.task().timeLimit);
  lua_pushstring(L, trialOutcomeName(judge.outcome()));  // interned constant: no new string after the first
  lua_setfield(L, data, "outcome");
  lua_pop(L, 1);
}

void LevelScript::setTiming(const TrialTiming& timing) { sandbox_->setTiming(timing); }

bool LevelScript::call(int functionRef, const std::string& where, const TrialObservation& obs, TaskJudge& judge,
                       const char* reason, bool perTick) {
  if (functionRef == LUA_NOREF) return true;
  lua_State* L = sandbox_->state();
  refreshView(obs, judge);
  lua_checkstack(L, 4);
  lua_rawgeti(L, LUA_REGISTRYINDEX, functionRef);
  lua_rawgeti(L, LUA_REGISTRYINDEX, viewRef_);
  int nargs = 1;
  if (reason != nullptr) {
    lua_pushstring(L, reason);
    nargs = 2;
  }
  activeJudge_ = &judge;
  activeTime_ = obs.time;
  ++callbackCalls_;
  try {
    sandbox_->advanceRun(obs.time);
    if (perTick)
      sandbox_->callPerTick(nargs, 0, where);
    else
      sandbox_->call(nargs, 0, where);
  } catch (const ScriptError& e) {
    activeJudge_ = nullptr;
    scriptError_ = std::string("script error: ") + e.what();
    if (judge.finished()) endCallbackError_ = scriptError_;  // too late to change the outcome; not to be lost
    judge.finish(TrialOutcome::Failure, scriptError_, obs.time);
    return false;
  }
  activeJudge_ = nullptr;
  return true;
}

void LevelScript::start(const TrialObservation& obs, TaskJudge& judge) {
  started_ = true;
  endReported_ = false;
  startTime_ = obs.time;
  updateIndex_ = 0;
  nextUpdate_ = startTime_ + period_;
  call(onStartRef_, whereStart_, obs, judge, nullptr);
}

void LevelScript::update(const TrialObservation& obs, TaskJudge& judge) {
  if (!started_) start(obs, judge);
  // 1 ns slack: the host's summed time steps land a hair before k * period.
  if (!judge.finished() && onUpdateRef_ != LUA_NOREF && obs.time >= nextUpdate_ - 1e-9) {
    // The schedule is k * period from the start, so calls do not drift; a
    // host that ticks slower than the rate gets one call per tick.
    while (startTime_ + static_cast<double>(updateIndex_ + 1) * period_ <= obs.time + 1e-9) ++updateIndex_;
    nextUpdate_ = startTime_ + static_cast<double>(updateIndex_ + 1) * period_;
    call(onUpdateRef_, whereUpdate_, obs, judge, nullptr, /*perTick=*/true);
  }
  if (judge.finished() && !endReported_) {
    endReported_ = true;
    // After a script error the level's own handlers are not trusted to run.
    if (judge.reason().rfind("script error: ", 0) == 0) return;
    if (judge.outcome() == TrialOutcome::Success)
      call(onSuccessRef_, whereSuccess_, obs, judge, nullptr);
    else
      call(onFailRef_, whereFail_, obs, judge, std::string(judge.reason()).c_str());
  }
}

ScoreResult LevelScript::score(const TrialSummary& summary) {
  ScoreResult result;
  if (scoreRef_ == LUA_NOREF) return result;
  lua_State* L = sandbox_->state();
  lua_checkstack(L, 6);
  lua_rawgeti(L, LUA_REGISTRYINDEX, scoreRef_);
  lua_createtable(L, 0, 16);
  const int table = lua_gettop(L);
  lua_pushboolean(L, summary.outcome == TrialOutcome::Success);
  lua_setfield(L, table, "success");
  lua_pushstring(L, summary.reason.c_str());
  lua_setfield(L, table, "reason");
  setNumber(L, table, "time", summary.time);
  lua_pushinteger(L, summary.ticks);
  lua_setfield(L, table, "ticks");
  lua_pushinteger(L, summary.stagesPassed);
  lua_setfield(L, table, "stages_passed");
  lua_pushinteger(L, summary.stageCount);
  lua_setfield(L, table, "stage_count");
  setNumber(L, table, "contact_path", summary.contactPath);
  setNumber(L, table, "point_path", summary.pointPath);
  setNumber(L, table, "effort", summary.effort);
  setNumber(L, table, "smoothness", summary.smoothness);
  setNumber(L, table, "best_margin", summary.bestMargin);
  setNumber(L, table, "final_margin", summary.finalMargin);
  setNumber(L, table, "time_limit", def_.task.timeLimit);
  lua_createtable(L, 0, static_cast<int>(summary.finalComponents.size()));
  for (const ComponentStatus& c : summary.finalComponents) {
    lua_createtable(L, 0, 3);
    const int entry = lua_gettop(L);
    setNumber(L, entry, "error", c.error);
    setNumber(L, entry, "margin", c.margin);
    setNumber(L, entry, "tolerance", c.tolerance);
    lua_setfield(L, entry - 1, taskVariableName(c.variable));
  }
  lua_setfield(L, table, "final_components");
  try {
    const int results = sandbox_->call(1, 1, whereScore_);
    (void)results;
  } catch (const ScriptError& e) {
    result.error = std::string("script error: ") + e.what();
    return result;
  }
  const bool isNumber = lua_type(L, -1) == LUA_TNUMBER;
  const double value = isNumber ? lua_tonumber(L, -1) : 0.0;
  const std::string got = describeLuaValue(L, -1);
  lua_pop(L, 1);
  if (!isNumber || !std::isfinite(value)) {
    result.error = "script error: " + whereScore_ + ": must return a finite number, got " + got;
    return result;
  }
  result.score = value;
  result.medal = medalFor(value);
  return result;
}

Medal LevelScript::medalFor(double value) const {
  const ScoringDef& s = def_.scoring;
  if (!s.hasMedals) return Medal::None;
  if (value >= s.gold) return Medal::Gold;
  if (value >= s.silver) return Medal::Silver;
  if (value >= s.bronze) return Medal::Bronze;
  return Medal::None;
}

std::vector<LevelMessage> LevelScript::takeMessages() {
  std::vector<LevelMessage> out;
  out.swap(messages_);
  messages_.reserve(16);
  return out;
}

}  // namespace hemiroll::script
