#include "engine/task/TaskJudge.h"

#include <cmath>
#include <limits>

namespace hemiroll::task {

namespace {

// Summed fixed steps carry rounding of ~1e-13 s after hours; a hold or a
// time limit is reached 1 ns early rather than one whole tick late (a 60 s
// limit ended at 60.001 s, 60001 ticks, since 60000 steps of 1 ms sum to
// just under 60).
constexpr double kHoldSlack = 1e-9;

// Strictly inside (the edge belongs to neither side).
bool strictlyInside(const ZoneDef& zone, double u, double v) {
  if (zone.shape == ZoneShape::Circle) {
    const double du = u - zone.center[0], dv = v - zone.center[1];
    return du * du + dv * dv < zone.radius * zone.radius;
  }
  return u > zone.min[0] && u < zone.max[0] && v > zone.min[1] && v < zone.max[1];
}

bool strictlyOutside(const ZoneDef& zone, double u, double v) {
  if (zone.shape == ZoneShape::Circle) {
    const double du = u - zone.center[0], dv = v - zone.center[1];
    return du * du + dv * dv > zone.radius * zone.radius;
  }
  return u < zone.min[0] || u > zone.max[0] || v < zone.min[1] || v > zone.max[1];
}

double valueOf(TaskVariable variable, const physics::ForceDrivenState& x) {
  if (variable == TaskVariable::omega_norm) {
    using namespace physics::force_slot;
    return std::sqrt(x[w_x] * x[w_x] + x[w_y] * x[w_y] + x[w_z] * x[w_z]);
  }
  return x[static_cast<int>(variable)];
}

}  // namespace

const char* trialOutcomeName(TrialOutcome outcome) {
  switch (outcome) {
    case TrialOutcome::Running: return "running";
    case TrialOutcome::Success: return "success";
    case TrialOutcome::Failure: return "failure";
  }
  return "?";
}

TaskJudge::TaskJudge(const TaskDef& task) : original_(task), task_(task) {
  components_.reserve(kTaskVariableCount);
  reset();
}

void TaskJudge::reset() {
  task_ = original_;
  for (StageDef& stage : task_.stages) stage.targets.reserve(kTaskVariableCount);
  outcome_ = TrialOutcome::Running;
  externalReason_.clear();
  reason_ = trial_reason::kRunning;
  finishTime_ = 0.0;
  stage_ = 0;
  stagesPassed_ = 0;
  stagePassTimes_.clear();
  stagePassTimes_.reserve(task_.stages.size());  // judging a tick allocates nothing
  held_ = 0.0;
  insideSince_ = 0.0;
  wasInside_ = false;
  allInside_ = false;
  zoneHit_ = -1;
  holdBreak_ = {};
  loadComponents();
}

void TaskJudge::loadComponents() {
  components_.clear();  // keeps the reserved capacity
  const StageDef* stage = currentStage();
  if (stage != nullptr)
    for (const TargetDef& target : stage->targets) {
      ComponentStatus c;
      c.variable = target.variable;
      c.target = target.value;
      c.tolerance = target.tolerance;
      c.error = std::numeric_limits<double>::infinity();
      c.margin = -std::numeric_limits<double>::infinity();
      components_.push_back(c);
    }
  worstNormalized_ = components_.empty() ? std::numeric_limits<double>::infinity()
                                         : -std::numeric_limits<double>::infinity();
}

const StageDef* TaskJudge::currentStage() const {
  return stage_ < stageCount() ? &task_.stages[static_cast<std::size_t>(stage_)] : nullptr;
}

double TaskJudge::requiredHold() const {
  const StageDef* stage = currentStage();
  return stage != nullptr ? stage->hold : 0.0;
}

std::span<const ComponentStatus> TaskJudge::components() const { return components_; }

void TaskJudge::end(TrialOutcome outcome, const char* reason, double time) {
  outcome_ = outcome;
  reason_ = reason;
  finishTime_ = time;
}

void TaskJudge::preview(const physics::ForceDrivenState& state) {
  if (!finished() && currentStage() != nullptr) evaluateStage(state);
}

void TaskJudge::recordHoldBreak(double time) {
  const ComponentStatus* furthest = nullptr;
  for (const ComponentStatus& c : components_)
    if (!c.inside && (!furthest || c.normalizedMargin() < furthest->normalizedMargin())) furthest = &c;
  if (!furthest) return;
  holdBreak_.happened = true;
  holdBreak_.variable = furthest->variable;
  holdBreak_.time = time;
  holdBreak_.excess = -furthest->margin;
  holdBreak_.heldFor = held_;
}

void TaskJudge::evaluateStage(const physics::ForceDrivenState& state) {
  bool inside = true;
  double worst = std::numeric_limits<double>::infinity();
  for (ComponentStatus& c : components_) {
    double error = valueOf(c.variable, state) - c.target;
    // psi is continuous; the orientation repeats every 2 pi. remainder is
    // exact in IEEE arithmetic, so this stays deterministic.
    if (c.variable == TaskVariable::psi) error = std::remainder(error, 2.0 * 3.141592653589793);
    c.error = error;
    c.margin = c.tolerance - std::abs(error);
    c.inside = c.margin >= 0.0;
    inside = inside && c.inside;
    const double normalized = c.margin / c.tolerance;
    if (normalized < worst) worst = normalized;
  }
  allInside_ = inside;
  worstNormalized_ = worst;
}

TrialOutcome TaskJudge::judge(const JudgeInput& input) {
  if (finished()) return outcome_;
  const double t = input.time;
  const physics::ForceDrivenState& x = input.state;
  if (!x.allFinite() || !std::isfinite(t) || input.event == physics::DomainEvent::NonFinite) {
    end(TrialOutcome::Failure, trial_reason::kNonFinite, t);
    return outcome_;
  }
  if (input.event == physics::DomainEvent::TippedOver && task_.failure.tipOver) {
    end(TrialOutcome::Failure, trial_reason::kTippedOver, t);
    return outcome_;
  }
  if (input.event == physics::DomainEvent::LeftFace && task_.failure.offFace) {
    end(TrialOutcome::Failure, trial_reason::kLeftFace, t);
    return outcome_;
  }
  const double u = x[physics::force_slot::u_a], v = x[physics::force_slot::v_a];
  if (task_.failure.area && strictlyOutside(*task_.failure.area, u, v)) {
    end(TrialOutcome::Failure, trial_reason::kLeftArea, t);
    return outcome_;
  }
  for (std::size_t i = 0; i < task_.forbidden.size(); ++i)
    if (strictlyInside(task_.forbidden[i], u, v)) {
      zoneHit_ = static_cast<int>(i);
      end(TrialOutcome::Failure, trial_reason::kForbiddenZone, t);
      return outcome_;
    }

  while (currentStage() != nullptr) {
    evaluateStage(x);
    if (!allInside_) {
      if (wasInside_) recordHoldBreak(t);
      wasInside_ = false;
      held_ = 0.0;
      break;
    }
    if (!wasInside_) {
      wasInside_ = true;
      insideSince_ = t;
    }
    held_ = t - insideSince_;
    if (held_ < currentStage()->hold - kHoldSlack) break;
    ++stagesPassed_;
    stagePassTimes_.push_back(t);
    if (stage_ + 1 == stageCount()) {
      // Success. components_ keep the last stage's values for the summary.
      ++stage_;
      end(TrialOutcome::Success, trial_reason::kTargetHeld, t);
      return outcome_;
    }
    // Passed: the next stage starts on this tick with a fresh timer.
    ++stage_;
    wasInside_ = false;
    held_ = 0.0;
    holdBreak_ = {};
    loadComponents();
  }

  if (t >= task_.timeLimit - kHoldSlack) {
    if (task_.watchOnly())
      end(TrialOutcome::Success, trial_reason::kWatched, t);
    else
      end(TrialOutcome::Failure, trial_reason::kTimeLimit, t);
  }
  return outcome_;
}

void TaskJudge::slotTargets(std::array<double, 12>& value, std::array<double, 12>& tolerance,
                            std::array<bool, 12>& set) const {
  value.fill(0.0);
  tolerance.fill(0.0);
  set.fill(false);
  for (const ComponentStatus& c : components_) {
    const int slot = static_cast<int>(c.variable);
    if (slot >= 12) continue;
    value[static_cast<std::size_t>(slot)] = c.target;
    tolerance[static_cast<std::size_t>(slot)] = c.tolerance;
    set[static_cast<std::size_t>(slot)] = true;
  }
}

std::string TaskJudge::setTarget(int stageIndex, TaskVariable variable, double value, double tolerance) {
  if (stageIndex < 0 || stageIndex >= stageCount())
    return "stage " + std::to_string(stageIndex + 1) + " does not exist (the task has " +
           std::to_string(stageCount()) + ")";
  if (!std::isfinite(value)) return std::string("the target of ") + taskVariableName(variable) + " is not finite";
  if (!std::isfinite(tolerance) || tolerance <= 0.0)
    return std::string("the tolerance of ") + taskVariableName(variable) + " must be a positive finite number";
  auto& targets = task_.stages[static_cast<std::size_t>(stageIndex)].targets;
  auto at = targets.begin();
  while (at != targets.end() && at->variable < variable) ++at;
  if (at != targets.end() && at->variable == variable) {
    at->value = value;
    at->tolerance = tolerance;
  } else {
    targets.insert(at, TargetDef{variable, value, tolerance});
  }
  if (stageIndex == stage_) {
    loadComponents();
    wasInside_ = false;  // the band moved: the hold starts again
    held_ = 0.0;
  }
  return {};
}

void TaskJudge::removeTarget(int stageIndex, TaskVariable variable) {
  if (stageIndex < 0 || stageIndex >= stageCount()) return;
  auto& targets = task_.stages[static_cast<std::size_t>(stageIndex)].targets;
  for (auto it = targets.begin(); it != targets.end(); ++it)
    if (it->variable == variable) {
      targets.erase(it);
      break;
    }
  if (stageIndex == stage_) {
    loadComponents();
    wasInside_ = false;
    held_ = 0.0;
  }
}

void TaskJudge::finish(TrialOutcome outcome, std::string reason, double time) {
  if (finished() || outcome == TrialOutcome::Running) return;
  externalReason_ = std::move(reason);
  outcome_ = outcome;
  reason_ = externalReason_;
  finishTime_ = time;
}

}  // namespace hemiroll::task
