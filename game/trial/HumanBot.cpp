#include "game/trial/HumanBot.h"

#include <cmath>

#include "engine/physics/Orientation.h"
#include "engine/physics/StateKinematics.h"
#include "engine/physics/StateLayout.h"
#include "engine/script/ScriptError.h"
#include "game/trial/HintCoach.h"

namespace hemiroll::game {

using physics::Vec2;
using physics::Vec3;

namespace {

// The face's normal in the scene for a state (eq. 6 applied to k).
Vec3 faceNormalOf(const physics::ForceDrivenState& x) {
  using namespace physics::force_slot;
  return physics::makeOrientation(x[u_o], x[v_o], x[psi]).faceNormal();
}

}  // namespace

human::ScreenView screenViewOf(const script::BotObservation& obs) {
  using namespace physics::force_slot;
  human::ScreenView v;
  v.time = obs.time;
  v.contact = Vec2(obs.contact[0], obs.contact[1]);
  v.normal = physics::vec3Of(obs.normal);
  v.mass = physics::vec3Of(obs.mass);
  v.proxy = physics::vec3Of(obs.proxy);
  v.spin = obs.state[w_z];
  v.engaged = obs.engaged;
  v.contactTargetSet = obs.targetSet[u_a] || obs.targetSet[v_a];
  if (v.contactTargetSet) {
    // A band on one coordinate only: the other is wherever the contact is.
    v.contactTarget = Vec2(obs.targetSet[u_a] ? obs.target[u_a] : obs.contact[0],
                           obs.targetSet[v_a] ? obs.target[v_a] : obs.contact[1]);
    v.contactTolerance = obs.targetSet[u_a] ? obs.tolerance[u_a] : obs.tolerance[v_a];
  }
  v.uprightRequired = obs.targetSet[x_p] || obs.targetSet[y_p] || obs.targetSet[u_o] || obs.targetSet[v_o];
  if (obs.targetSet[u_o] || obs.targetSet[v_o]) {
    // The lean the task asks for, as the face's normal would show it: the
    // state with the target's u_co (a band on one angle: the other as is).
    physics::ForceDrivenState at = physics::forceStateOf(obs.state);
    if (obs.targetSet[u_o]) at[u_o] = obs.target[u_o];
    if (obs.targetSet[v_o]) at[v_o] = obs.target[v_o];
    v.leanTargetSet = true;
    v.leanTarget = faceNormalOf(at);
    v.leanTolerance = obs.targetSet[u_o] ? obs.tolerance[u_o] : obs.tolerance[v_o];
  }
  if (obs.targetSet[psi]) {
    v.headingSet = true;
    v.headingError = std::remainder(obs.target[psi] - obs.state[psi], 2.0 * M_PI);
    v.headingTolerance = obs.tolerance[psi];
  }
  if (obs.targetSet[w_z]) v.spinTolerance = obs.tolerance[w_z];
  else if (obs.omegaNormSet) v.spinTolerance = obs.omegaNormTolerance;
  v.stage = obs.stage;
  return v;
}

HumanBot::HumanBot(const HumanBotOptions& options) : options_(options) {}
HumanBot::~HumanBot() = default;

void HumanBot::init(const script::BotLevelInfo& info, std::int64_t seed) {
  radius_ = info.params.radius;
  human::HumanDef person = options_.human;
  if (info.memory != nullptr && options_.learns) {
    const int practised = static_cast<int>(info.memory->get(kPracticeTrials).value_or(0.0));
    person.noise = human::practisedNoise(options_.practice, options_.human.noise, practised);
    info.memory->set(kPracticeTrials, practised + 1);
    info.memory->set(kMotorNoise, person.noise);
  }
  model_.emplace(person, options_.technique, info.params.radius, info.dt, static_cast<std::uint64_t>(seed));
  holding_ = false;
  tick_ = info.dt;
  mouseHand_.reset();
  if (person.device == human::HandDevice::MouseHand) {
    if (const std::string bad = haptics::validateHandSpring(options_.mouseHand); !bad.empty())
      throw script::ScriptError("human: mouse-hand: " + bad);
    mouseHand_.emplace(options_.mouseHand);
  }
  coach_.reset();
  if (options_.aids) {
    coach_ = std::make_unique<HintCoach>();
    coach_->init(info, seed);
  }
}

script::BotAction HumanBot::act(const script::BotObservation& obs) {
  if (!model_) throw script::ScriptError("human: act before init");
  if (!holding_) {  // takes hold where the mass point is, as a player clicking on it
    holding_ = true;
    model_->takeHold(physics::vec3Of(obs.mass));
    if (mouseHand_) mouseHand_->reset(physics::vec3Of(obs.mass));
  }
  human::ScreenView view = screenViewOf(obs);
  if (coach_) {
    view.hint = coach_->hint(obs);
    view.forceCueShown = true;
    view.forceCue = physics::vec3Of(obs.force);
  }
  human::HandPose hand = model_->act(view, physics::vec3Of(obs.deviceForce));
  if (mouseHand_) {
    // The person's hand moved the mouse; the game's hand, pulled by it and
    // pushed by the force the device renders, holds the proxy.
    mouseHand_->step(hand.position, hand.velocity, physics::vec3Of(obs.deviceForce), tick_);
    hand = {mouseHand_->position(), mouseHand_->velocity()};
  }
  script::BotAction action;
  action.position = physics::tripleOf(hand.position);
  action.velocity = physics::tripleOf(hand.velocity);
  action.hasVelocity = true;
  return action;
}

std::string HumanBot::giveUpReason() const { return {}; }

}  // namespace hemiroll::game
