#include "engine/script/LevelScriptApi.h"

#include <lua.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/script/LevelScript.h"
#include "engine/script/ScriptModules.h"

namespace hemiroll::script {

namespace {

constexpr std::size_t kMaxPendingMessages = 256;  // a runaway on_update cannot fill memory
constexpr std::size_t kMaxMessageBytes = 512;     // a HUD line, not a file: longer ones are cut

// Reads argument `arg` as one number or a list of `size` numbers into out.
// Plain C: may raise.
void readComponents(lua_State* L, int arg, int size, double* out, const char* what) {
  if (lua_type(L, arg) == LUA_TNUMBER) {
    for (int i = 0; i < size; ++i) out[i] = lua_tonumber(L, arg);
    return;
  }
  if (lua_type(L, arg) != LUA_TTABLE || static_cast<int>(lua_rawlen(L, arg)) != size)
    luaL_error(L, "%s: expected a number or a list of %d numbers", what, size);
  for (int i = 0; i < size; ++i) {
    lua_rawgeti(L, arg, i + 1);
    int isNumber = 0;
    out[i] = lua_tonumberx(L, -1, &isNumber);
    lua_pop(L, 1);
    if (!isNumber || lua_type(L, arg) != LUA_TTABLE) luaL_error(L, "%s: expected a list of %d numbers", what, size);
  }
}

}  // namespace

// The C functions behind hemiroll.message, set_target, ... They reach the
// LevelScript through the registry and raise "only inside a callback" when
// no callback is running. C++ work happens in the member helpers, whose
// frames end before any Lua error is raised.

struct LevelScriptFunctions {
  static LevelScript& active(lua_State* L, const char* function) {
    lua_getfield(L, LUA_REGISTRYINDEX, LevelScriptApi::kRegistryKey);
    auto* self = static_cast<LevelScript*>(lua_touserdata(L, -1));
    lua_pop(L, 1);
    if (self == nullptr || self->activeJudge_ == nullptr)
      luaL_error(L, "hemiroll.%s is only available inside a level callback", function);
    return *self;
  }

  static bool addMessage(LevelScript& self, const char* text, std::size_t length, double seconds) noexcept try {
    if (self.messages_.size() < kMaxPendingMessages)
      self.messages_.push_back({self.activeTime_, std::string(text, std::min(length, kMaxMessageBytes)), seconds});
    return true;
  } catch (...) {
    return false;
  }

  static int message(lua_State* L) {
    LevelScript& self = active(L, "message");
    std::size_t length = 0;
    const char* text = luaL_checklstring(L, 1, &length);
    const double seconds = luaL_optnumber(L, 2, 3.0);
    luaL_argcheck(L, std::isfinite(seconds) && seconds > 0.0, 2, "seconds must be positive");
    if (!addMessage(self, text, length, seconds)) return luaL_error(L, "hemiroll.message: out of memory");
    return 0;
  }

  // Applies set_target/clear_target for `count` variables; false with
  // apiError_ set when the judge refuses.
  static bool applyTargets(LevelScript& self, const TaskVariable* variables, int count, const double* values,
                           const double* tolerances, bool clear) noexcept try {
    TaskJudge& judge = *self.activeJudge_;
    for (int i = 0; i < count; ++i) {
      if (clear) {
        judge.removeTarget(judge.stage(), variables[i]);
        continue;
      }
      const std::string problem = judge.setTarget(judge.stage(), variables[i], values[i], tolerances[i]);
      if (!problem.empty()) {
        self.apiError_ = "hemiroll.set_target: " + problem;
        return false;
      }
    }
    return true;
  } catch (...) {
    self.apiError_ = "hemiroll.set_target: out of memory";
    return false;
  }

  static int changeTarget(lua_State* L, bool clear) {
    LevelScript& self = active(L, clear ? "clear_target" : "set_target");
    const char* name = luaL_checkstring(L, 1);
    TaskVariable variables[3] = {};
    int size = 1;
    if (const auto group = taskVariableGroup(name)) {
      size = group->size;
      for (int i = 0; i < size; ++i) variables[i] = group->members[static_cast<std::size_t>(i)];
    } else if (const auto variable = taskVariableFromName(name)) {
      variables[0] = *variable;
    } else {
      return luaL_error(L, "hemiroll.%s: unknown variable '%s'", clear ? "clear_target" : "set_target", name);
    }
    if (self.activeJudge_->currentStage() == nullptr) return luaL_error(L, "hemiroll.set_target: the task has no current stage");
    double values[3] = {}, tolerances[3] = {};
    if (!clear) {
      readComponents(L, 2, size, values, "hemiroll.set_target value");
      readComponents(L, 3, size, tolerances, "hemiroll.set_target tol");
    }
    if (!applyTargets(self, variables, size, values, tolerances, clear)) return luaL_error(L, "%s", self.apiError_.c_str());
    return 0;
  }
  static int setTarget(lua_State* L) { return changeTarget(L, false); }
  static int clearTarget(lua_State* L) { return changeTarget(L, true); }

  static bool end(LevelScript& self, TrialOutcome outcome, const char* text, std::size_t length) noexcept try {
    const std::string reason = text != nullptr ? "level: " + std::string(text, length)
                                               : std::string(outcome == TrialOutcome::Success ? "level: success" : "level: failure");
    self.activeJudge_->finish(outcome, reason, self.activeTime_);
    return true;
  } catch (...) {
    return false;
  }

  static int finishWith(lua_State* L, TrialOutcome outcome, const char* function) {
    LevelScript& self = active(L, function);
    std::size_t length = 0;
    const char* text = outcome == TrialOutcome::Failure ? luaL_checklstring(L, 1, &length) : luaL_optlstring(L, 1, nullptr, &length);
    if (!end(self, outcome, text, length)) return luaL_error(L, "hemiroll.%s: out of memory", function);
    return 0;
  }
  static int succeed(lua_State* L) { return finishWith(L, TrialOutcome::Success, "succeed"); }
  static int fail(lua_State* L) { return finishWith(L, TrialOutcome::Failure, "fail"); }

  static int stage(lua_State* L) {
    LevelScript& self = active(L, "stage");
    lua_pushinteger(L, self.activeJudge_->stage() + 1);
    return 1;
  }
};

void LevelScript::installApi(LuaSandbox& sandbox) {
  lua_State* L = sandbox.state();
  pushEngineTable(sandbox);
  const luaL_Reg functions[] = {{"message", &LevelScriptFunctions::message},     {"set_target", &LevelScriptFunctions::setTarget},
                                {"clear_target", &LevelScriptFunctions::clearTarget}, {"succeed", &LevelScriptFunctions::succeed},
                                {"fail", &LevelScriptFunctions::fail},           {"stage", &LevelScriptFunctions::stage},
                                {nullptr, nullptr}};
  luaL_setfuncs(L, functions, 0);
  lua_pop(L, 1);
}


}  // namespace hemiroll::script
