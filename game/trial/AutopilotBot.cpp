#include "game/trial/AutopilotBot.h"

#include <algorithm>

#include "engine/physics/StateKinematics.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::game {

AutopilotBot::AutopilotBot(const AutopilotBotOptions& options) : options_(options) {}
AutopilotBot::~AutopilotBot() = default;

void AutopilotBot::init(const script::BotLevelInfo& info, std::int64_t seed) {
  if (info.coupling.visualOnly)
    // "Visual only" renders no force but drives the model as its method
    // would; the level info does not say which, so the autopilot cannot
    // model it.
    throw script::ScriptError("autopilot: a visual-only coupling hides the method that drives the model");
  autopilot::AutopilotDef def;
  def.params = info.params;
  def.coupling = info.coupling;
  def.dt = info.dt;
  def.workspace.centre = physics::vec3Of(info.workspaceCentre);
  def.workspace.radius = info.workspaceRadius;
  def.budget = options_.budget;
  def.seed = static_cast<std::uint64_t>(seed);
  def.plannerThread = options_.plannerThread;
  def.plannerNice = options_.plannerNice;
  def.handStiffens = options_.holdsProxy;
  autopilot_ = std::make_unique<autopilot::Autopilot>(def);
}

script::BotAction AutopilotBot::act(const script::BotObservation& obs) {
  if (!autopilot_) throw script::ScriptError("autopilot: act before init");
  input_.time = obs.time;
  for (int i = 0; i < 12; ++i) input_.state[i] = obs.state[static_cast<std::size_t>(i)];
  input_.massPosition = physics::vec3Of(obs.mass);
  input_.massVelocity = physics::vec3Of(obs.massVelocity);
  input_.engaged = obs.engaged;
  input_.forceShare = obs.forceShare;
  input_.stage = obs.stage;
  input_.goal = goalOf(obs);
  const autopilot::ProxyCommand command = autopilot_->act(input_);
  script::BotAction action;
  action.position = physics::tripleOf(command.position);
  action.velocity = physics::tripleOf(command.velocity);
  action.hasVelocity = true;
  return action;
}

void AutopilotBot::letGoOfProxy() {
  options_.holdsProxy = false;
  if (autopilot_) autopilot_->setHandStiffens(false);
}

std::string AutopilotBot::giveUpReason() const {
  if (!autopilot_ || autopilot_->failure().empty()) return {};
  return "autopilot: " + autopilot_->failure();
}

autopilot::Goal goalOf(const script::BotObservation& obs) {
  autopilot::Goal goal;
  goal.target = obs.target;
  goal.tolerance = obs.tolerance;
  goal.set = obs.targetSet;
  goal.omegaNormSet = obs.omegaNormSet;
  goal.omegaNormTarget = obs.omegaNormTarget;
  goal.omegaNormTolerance = obs.omegaNormTolerance;
  goal.hold = obs.holdTime;
  goal.zoneCount = std::min(obs.zoneCount, autopilot::Goal::kMaxZones);
  for (int i = 0; i < goal.zoneCount; ++i) goal.zones[static_cast<std::size_t>(i)] = obs.zones[static_cast<std::size_t>(i)];
  return goal;
}

haptics::GuideSample guideSampleOf(AutopilotBot& autopilot, const script::BotObservation& obs) {
  haptics::GuideSample sample;
  sample.time = obs.time;
  if (!autopilot.giveUpReason().empty()) return sample;  // no plan any more
  const script::BotAction plan = autopilot.act(obs);
  sample.position = plan.position;
  if (plan.hasVelocity) sample.velocity = plan.velocity;
  sample.valid = autopilot.giveUpReason().empty() && physics::vec3Of(sample.position).allFinite() && physics::vec3Of(sample.velocity).allFinite();
  return sample;
}

}  // namespace hemiroll::game
