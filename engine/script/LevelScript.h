#pragma once
// The Lua half of a loaded level: its callbacks and its score function, run
// in the sandbox the level was loaded into (created by LevelLoader).
//
// Callbacks (all optional), at simulated times:
//   on_start(state)           once, before the first tick is judged;
//   on_update(state)          every 1 / callbacks.rate seconds of simulated
//                             time (the host calls update() every tick; it
//                             calls Lua only when one is due);
//   on_success(state)         once, when the judge reports success;
//   on_fail(state, reason)    once, when the trial fails (any reason).
// `state` is ONE read-only table, built at load time and refreshed in place
// before each call (fields in docs/LEVELS.md, "The state view"); nothing is
// allocated for it per call. While a callback runs, the engine table offers
//   hemiroll.message(text [, seconds])     a message for the HUD (default 3 s);
//   hemiroll.set_target(name, value, tol)  change/add a target of the current
//                                          stage (name as in task.targets);
//   hemiroll.clear_target(name)            drop a target of the current stage;
//   hemiroll.succeed([text])               end the trial with success;
//   hemiroll.fail(text)                    end it with failure, reason "level: text";
//   hemiroll.stage()                       the current stage, 1-based.
// They raise "only inside a callback" at load time.
//
// Any error inside a callback (run-time error, quota, memory, a bad call to
// the API) ends the trial through TaskJudge::finish with reason
// "script error: file:line: message"; nothing propagates to the host.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/physics/StateLayout.h"
#include "engine/task/LevelDef.h"
#include "engine/script/LuaSandbox.h"
#include "engine/task/TaskJudge.h"
#include "engine/task/TrialSummary.h"
#include "engine/script/TaskNames.h"
#include "engine/script/TrialTiming.h"

namespace hemiroll::script {

// What the host knows about a tick beyond the judge (all optional for the
// level: zero when the host has none).
struct TrialObservation {
  double time = 0.0;                                                    // [s]
  physics::ForceDrivenState state = physics::ForceDrivenState::Zero();  // 12-state
  physics::Vec3 proxy = physics::Vec3::Zero();                          // scene [m]
  physics::Vec3 handForce = physics::Vec3::Zero();                      // F_h on the mass point [N]
};

struct LevelMessage {
  double time = 0.0;      // simulated time it was raised [s]
  std::string text;
  double duration = 3.0;  // how long to show it [s]
};

struct ScoreResult {
  std::optional<double> score;  // nullopt: the level has no score function, or it failed
  Medal medal = Medal::None;
  std::string error;            // "script error: file:line: message" when the function failed
};

class LevelScript {
 public:
  // Used by LevelLoader: takes the level's sandbox and the table the file
  // returned (on top of the sandbox's stack, popped).
  LevelScript(std::shared_ptr<LuaSandbox> sandbox, const LevelDef& def);
  ~LevelScript();
  LevelScript(const LevelScript&) = delete;
  LevelScript& operator=(const LevelScript&) = delete;

  // Installs hemiroll.message, set_target, clear_target, succeed, fail and
  // stage into the sandbox's engine table before the level file runs (they
  // raise "only inside a callback" until a LevelScript calls back).
  static void installApi(LuaSandbox& sandbox);

  // How the trial runs (TrialTiming.h): headless, the level's Lua gets the
  // trial's time budget from now on; real time, on_update the tick's CPU
  // budget. Set by the trial runner before start.
  void setTiming(const TrialTiming& timing);
  // on_start; arms the on_update schedule at obs.time.
  void start(const TrialObservation& obs, TaskJudge& judge);
  // Call every tick after judging it. Runs on_update when due, then
  // on_success / on_fail once when the judge has just finished.
  void update(const TrialObservation& obs, TaskJudge& judge);

  // The level's score function on `summary` (under the per-call quota), and
  // the medal from the level's thresholds.
  ScoreResult score(const TrialSummary& summary);
  Medal medalFor(double score) const;

  // Messages raised since the last call, oldest first.
  std::vector<LevelMessage> takeMessages();

  long long callbackCalls() const { return callbackCalls_; }
  // The last callback error ("script error: file:line: message"), also when
  // it came after the trial had ended (on_success / on_fail); "" = none.
  const std::string& scriptError() const { return scriptError_; }
  // on_success or on_fail failed after the judge had ended the trial: the
  // outcome stands, and this says what went wrong ("" when nothing did).
  const std::string& endCallbackError() const { return endCallbackError_; }
  LuaSandbox& sandbox() { return *sandbox_; }

 private:
  bool call(int functionRef, const std::string& where, const TrialObservation& obs, TaskJudge& judge,
            const char* reason, bool perTick = false);
  void refreshView(const TrialObservation& obs, const TaskJudge& judge);
  void buildView();
  void installApi();

  std::shared_ptr<LuaSandbox> sandbox_;
  LevelDef def_;
  int levelRef_ = -2;  // LUA_NOREF: registry references
  int onStartRef_ = -2, onUpdateRef_ = -2, onSuccessRef_ = -2, onFailRef_ = -2, scoreRef_ = -2;
  int viewRef_ = -2, viewDataRef_ = -2;
  std::string whereStart_, whereUpdate_, whereSuccess_, whereFail_, whereScore_;  // "file: callbacks.on_update"
  double period_ = 0.05;
  double startTime_ = 0.0;
  long long updateIndex_ = 0;
  double nextUpdate_ = 0.0;
  bool started_ = false;
  bool endReported_ = false;
  std::string scriptError_;
  std::string endCallbackError_;
  std::string apiError_;  // a message an API function raises (outlives the C frame)
  long long callbackCalls_ = 0;
  // Valid only while a callback runs (the API functions reach them).
  TaskJudge* activeJudge_ = nullptr;
  double activeTime_ = 0.0;
  std::vector<LevelMessage> messages_;

  friend struct LevelScriptFunctions;  // the C functions behind hemiroll.* (LevelScriptApi.cpp)
};

}  // namespace hemiroll::script
