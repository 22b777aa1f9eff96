#pragma once
// Judges a TaskDef against the simulation every tick, natively: per-component
// in/out of tolerance with margins, the hold timer, the current stage, and the
// outcome with its reason. It knows no particular level; it evaluates
// whatever the level declared (docs/LEVELS.md, "How a trial is judged").
//
// judge() allocates nothing, takes no lock and calls no Lua: it may run on
// the servo thread. Everything that may allocate (construction, setTarget,
// finish) is for the host thread between ticks.
//
// Order of checks in one tick (the first that applies decides):
//   1. a finished trial stays finished (judge() is then a no-op);
//   2. a non-finite state fails ("state not finite");
//   3. domain events: tip-over / off-face fail when the level says so;
//   4. the contact point leaving the level's area, or entering a forbidden
//      zone, fails (a point on a zone's edge is neither in nor out: allowed);
//   5. the current stage's components are evaluated; if all are inside, the
//      hold timer is the time since the first tick of this inside run (0 on
//      that tick), else it resets to 0; once it reaches the stage's hold
//      (less 1 ns, for the rounding of summed time steps) the next stage
//      starts on the same tick (it may pass at once if it is already
//      held with hold 0), and passing the last stage is success ("target
//      held");
//   6. time >= time limit fails ("time limit reached"), or succeeds for a
//      watch-only level ("watched to the end").
// So a target reached on the very tick the time runs out counts.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/physics/DomainEvents.h"
#include "engine/physics/StateLayout.h"
#include "engine/task/TaskDef.h"

namespace hemiroll::task {

enum class TrialOutcome : std::uint8_t { Running, Success, Failure };
const char* trialOutcomeName(TrialOutcome outcome);  // "running", "success", "failure"

// The reasons the judge itself gives (string constants: no allocation).
namespace trial_reason {
inline constexpr const char* kRunning = "";
inline constexpr const char* kTargetHeld = "target held";
inline constexpr const char* kWatched = "watched to the end";
inline constexpr const char* kTimeLimit = "time limit reached";
inline constexpr const char* kTippedOver = "tipped over";
inline constexpr const char* kLeftFace = "mass point left the face";
inline constexpr const char* kNonFinite = "state not finite";
inline constexpr const char* kLeftArea = "contact point left the area";
inline constexpr const char* kForbiddenZone = "contact point entered a forbidden zone";
}  // namespace trial_reason

// What the judge reads each tick.
struct JudgeInput {
  double time = 0.0;                                                     // [s]
  physics::ForceDrivenState state = physics::ForceDrivenState::Zero();   // 12-state
  physics::DomainEvent event = physics::DomainEvent::None;               // from the stepper
};

// One judged component of the current stage, as of the last judge().
struct ComponentStatus {
  TaskVariable variable = TaskVariable::x_p;
  double target = 0.0;     // [unit of the variable]
  double tolerance = 0.0;  // [unit of the variable]
  double error = 0.0;      // value - target (psi wrapped to (-pi, pi]) [unit]
  double margin = 0.0;     // tolerance - |error| [unit]; >= 0 inside
  bool inside = false;
  // margin / tolerance [-]: 1 on target, 0 on the band's edge, < 0 outside.
  double normalizedMargin() const { return margin / tolerance; }
};

// The last time every component was inside and one went out again (the hold
// timer reset): which, when, and how far out. What a player needs to know
// when every row looks green but the hold never completes.
struct HoldBreak {
  bool happened = false;
  TaskVariable variable = TaskVariable::x_p;  // the component furthest out on that tick
  double time = 0.0;                          // [s] the tick it went out
  double excess = 0.0;                        // |error| - tolerance on that tick [unit of the variable], > 0
  double heldFor = 0.0;                       // [s] the hold it broke
};

class TaskJudge {
 public:
  // Copies the task. Reserves room for later setTarget additions up to one
  // target per variable, so that judge() never allocates.
  explicit TaskJudge(const TaskDef& task);

  // Back to the start: stage 0, timer 0, running.
  void reset();

  // Judges one tick (see the order above) and returns the outcome.
  TrialOutcome judge(const JudgeInput& input);
  // The current stage's components for `state` (errors, margins, in/out),
  // judging nothing: no tick, no hold, no outcome. What a HUD shows before
  // the first tick (a trial waiting for the player to take hold).
  void preview(const physics::ForceDrivenState& state);

  TrialOutcome outcome() const { return outcome_; }
  bool finished() const { return outcome_ != TrialOutcome::Running; }
  // A trial_reason constant, or the message given to finish().
  std::string_view reason() const { return reason_; }
  double finishTime() const { return finishTime_; }  // [s]; valid once finished

  int stage() const { return stage_; }               // 0-based current stage
  int stageCount() const { return static_cast<int>(task_.stages.size()); }
  int stagesPassed() const { return stagesPassed_; }
  // When each passed stage was passed [s], in order.
  const std::vector<double>& stagePassTimes() const { return stagePassTimes_; }
  const StageDef* currentStage() const;              // nullptr when watch-only or all passed
  double holdTime() const { return held_; }          // [s] inside so far in this stage
  double requiredHold() const;                       // [s] of the current stage
  bool allInside() const { return allInside_; }      // every component of the current stage
  // The current stage's components, in variable order, as of the last judge().
  std::span<const ComponentStatus> components() const;
  // Smallest normalizedMargin() over the components (+inf when there are none).
  double worstNormalizedMargin() const { return worstNormalized_; }
  int forbiddenZoneHit() const { return zoneHit_; }  // index into task.forbidden; -1 = none
  // The last hold the current stage lost (happened == false: none yet).
  const HoldBreak& lastHoldBreak() const { return holdBreak_; }

  // The current stage's targets by state slot (omega_norm is not a slot and
  // is left out), for HUDs and bots: set[i] says whether slot i is judged.
  void slotTargets(std::array<double, 12>& value, std::array<double, 12>& tolerance,
                   std::array<bool, 12>& set) const;

  // Dynamic targets (host thread, between ticks): sets the target and
  // tolerance of `variable` in stage `stageIndex`, adding the component when
  // the stage has none for it. Returns an empty string on success or a
  // sentence saying what is wrong (stage out of range, tolerance <= 0,
  // non-finite value).
  std::string setTarget(int stageIndex, TaskVariable variable, double value, double tolerance);
  // Removes `variable` from stage `stageIndex` (no-op if absent).
  void removeTarget(int stageIndex, TaskVariable variable);

  // Ends the trial from outside (a script error, a level's own rule). No-op
  // when already finished.
  void finish(TrialOutcome outcome, std::string reason, double time);

  const TaskDef& task() const { return task_; }

 private:
  void evaluateStage(const physics::ForceDrivenState& state);
  void recordHoldBreak(double time);
  void end(TrialOutcome outcome, const char* reason, double time);

  void loadComponents();  // components_ from the current stage, within their reserved capacity

  TaskDef original_;  // as declared, for reset()
  TaskDef task_;      // with dynamic target changes
  std::vector<ComponentStatus> components_;  // capacity kTaskVariableCount, fixed
  TrialOutcome outcome_ = TrialOutcome::Running;
  const char* constantReason_ = trial_reason::kRunning;
  std::string externalReason_;
  std::string_view reason_ = trial_reason::kRunning;
  double finishTime_ = 0.0;
  int stage_ = 0;
  int stagesPassed_ = 0;
  std::vector<double> stagePassTimes_;
  double held_ = 0.0;
  double insideSince_ = 0.0;  // [s] time of the first tick of the current inside run
  bool wasInside_ = false;
  bool allInside_ = false;
  double worstNormalized_ = 0.0;
  int zoneHit_ = -1;
  HoldBreak holdBreak_;
};

}  // namespace hemiroll::task
