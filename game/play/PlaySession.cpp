#include "game/play/PlaySession.h"

#include <algorithm>
#include <stdexcept>

#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "engine/physics/StateKinematics.h"
#include "game/trial/DeviceProfiles.h"

namespace hemiroll::game {

namespace {

TrialRigDef rigDefOf(const PlaySessionDef& def, const task::LevelDef& level) {
  if (def.profile) {
    const std::string refusal = couplingRefusal(*def.profile, def.coupling.value_or(level.coupling), level.source);
    if (!refusal.empty()) throw std::invalid_argument(refusal);
  }
  TrialRigDef rig;
  rig.device = def.device;
  rig.coupling = def.coupling;
  rig.safety = def.safety;
  rig.guidance = def.guidance;
  rig.threaded = true;
  rig.requestRealtime = def.requestRealtime;
  rig.clock = def.clock;
  rig.faultsEndTrial = false;  // a safety fault pauses a person's trial
  rig.replayFile = def.replayFile;
  rig.levelHash = def.levelHash;
  return rig;
}

}  // namespace

void useDeviceProfile(PlaySessionDef& def, const task::DeviceProfileDef& profile) {
  def.profile = profile;
  def.deviceOptions.udp.spec = deviceSpecOf(profile);
  def.safety = safetyOf(profile, def.safety.value_or(haptics::SafetyDef{}));
}

PlaySession::PlaySession(script::LoadedLevel& level, const PlaySessionDef& def)
    : level_(level),
      mapping_(def.pointer),
      deviceName_(def.device),
      rig_(level, rigDefOf(def, level.def), [&](const haptics::ServoLoopDef& loop) { return makeDevice(def, loop); }) {
  clockStartsOnTakeHold_ = def.clockStartsOnTakeHold;
  if (def.watchAutopilot || def.guidance.active())
    companion_ = std::make_unique<AutopilotCompanion>(level.def, rig_.loop(), rig_.loopDef().mapping, autopilotHand_,
                                                      def.guidance.active());
  if (mouse_) {
    // The proxy starts on the mass point (the device origin is mapped to
    // where a level's mass point starts, at its height), so that a click
    // takes hold at once, without aiming or touching the wheel.
    const haptics::WorkspaceMapping& m = rig_.loopDef().mapping;
    const physics::Vec3 p = physics::massPointPosition(rig_.initial(), level.def.params.radius);
    const double zDevice = (p.z() - m.offset.z()) / m.scale;
    mapping_.wheel(zDevice / mapping_.def().wheelStep);
    sendPointer(/*jump=*/true);
  }
}

// The person's device (the mouse, or one the factory opens); watching, the
// autopilot's hand beside it behind a TakeoverDevice.
std::unique_ptr<haptics::HapticDevice> PlaySession::makeDevice(const PlaySessionDef& def,
                                                               const haptics::ServoLoopDef& loop) {
  std::unique_ptr<haptics::HapticDevice> player;
  if (haptics::isMouseDevice(def.device)) {
    auto mouse = std::make_unique<haptics::MouseDevice>(
        def.device == haptics::kMouseHandDevice
            ? haptics::mouseHandDef(def.deviceOptions.mouse, def.deviceOptions.mouseHand)
            : def.deviceOptions.mouse);
    mouse_ = mouse.get();
    player = std::move(mouse);
  } else {
    haptics::DeviceChoice choice = haptics::DeviceFactory().makeAndOpen(def.device, def.deviceOptions);
    if (!choice.device) throw std::runtime_error(def.device + ": " + choice.error);
    player = std::move(choice.device);
    if (def.device == haptics::kJoystickDevice) joystick_ = static_cast<haptics::SdlJoystickDevice*>(player.get());
  }
  player_ = player.get();
  if (!def.watchAutopilot) return player;
  auto hand = std::make_unique<HandoffBotDevice>(player->spec(), loop.mapping);
  autopilotHand_ = hand.get();
  auto takeover = std::make_unique<TakeoverDevice>(std::move(hand), std::move(player));
  takeover_ = takeover.get();
  return takeover;
}

PlaySession::~PlaySession() {
  if (companion_) companion_->stop();
  // The rig stops its loop, then closes the device on this (the SDL) thread.
}

void PlaySession::start() {
  started_ = true;
  startedAt_ = std::chrono::steady_clock::now();
  startLoopWhenReady();
}

// The bridge says "no client yet" until its first good state; starting the
// loop before that would trip its watchdog at once.
bool PlaySession::startLoopWhenReady() {
  if (rig_.loop().running() || stopped_) return true;
  if (!player_->ready()) {
    const char* why = player_->error();
    waitingFor_ = deviceName_ + ": " + (why ? why : "not ready");
    return false;
  }
  waitingFor_.clear();
  if (!judgeStarted_) {
    judgeStarted_ = true;
    // The level's callbacks run on the window's thread, once per frame for
    // the ticks it drains: each on_update has a frame's CPU as its deadline.
    level_.script->setTiming({.realtime = true, .tickSeconds = kWindowLuaTickSeconds});
    rig_.judging().start(rig_.initial());
  }
  if (rig_.judging().finished()) return true;   // on_start ended it
  if (holdsClock() && !takenHold_) return false;
  startedAt_ = std::chrono::steady_clock::now();
  if (autopilotHolds()) {
    // The autopilot's hand rests on the mass point until its first plan
    // lands (a few ms on its own thread; without this pose the loop would
    // read a device with nothing to say), and takes hold at once.
    autopilotHand_->publish(rig_.loopDef().startTime,
                            physics::massPointPosition(rig_.initial(), level_.def.params.radius), haptics::Vec3::Zero());
    post(haptics::ServoCommandKind::Engage);
  }
  rig_.startLoop();  // the replay log, then the servo thread
  if (companion_) {
    companion_->publishTask(rig_.judging().judge());  // the goal before the first plan
    companion_->start();
  }
  return true;
}

void PlaySession::sendPointer(bool jump) {
  if (mouse_) mouse_->setPointer(mapping_.position(), 0, jump);
}

void PlaySession::pointerMotion(double dx, double dy) {
  if (!mouse_) return;
  mapping_.moveBy(dx, dy);
  sendPointer(false);
}

void PlaySession::wheel(double notches) {
  if (!mouse_) return;
  mapping_.wheel(notches);
  sendPointer(false);
}

bool PlaySession::rumble(double strength) { return joystick_ != nullptr && joystick_->rumble(strength); }

haptics::Vec3 PlaySession::pointerScene() const {
  // The hand is known once the loop reads it; before, it rests on the pointer.
  if (autopilotHolds() || (handFeel() && rig_.loop().running())) {
    const haptics::Triple& p = snapshot().proxyPosition;
    return {p[0], p[1], p[2]};
  }
  return rig_.loopDef().mapping.positionToScene(mapping_.position());
}

void PlaySession::takeOver() {
  if (!autopilotHolds() || handoverPending_) return;
  if (mouse_) {
    companion_->stopDriving();
    // The pointer picks the proxy up where the autopilot left it: no jump,
    // no gap in the coupling.
    const haptics::Triple& p = snapshot().proxyPosition;
    const haptics::Vec3 device = (haptics::Vec3(p[0], p[1], p[2]) - rig_.loopDef().mapping.offset) / rig_.loopDef().mapping.scale;
    mapping_.moveTo(device.x(), device.y());
    sendPointer(/*jump=*/true);
    takeover_->handToPlayer();
  } else {
    // The player's hand is elsewhere and feels force: the autopilot lets go
    // first, then the device is handed over (frame() does, once disengaged)
    // and the player takes hold with the usual click and ramp-in. The
    // physics stands still meanwhile, as after the player letting go.
    post(haptics::ServoCommandKind::Disengage);
    handoverPending_ = true;
    freeze(Freeze::LetGo);
  }
}

void PlaySession::handOverWhenLetGo() {
  if (!handoverPending_ || snapshot().engagement != haptics::Engagement::Disengaged) return;
  companion_->stopDriving();
  takeover_->handToPlayer();
  handoverPending_ = false;
}

void PlaySession::enableHints() {
  if (companion_ || stopped_) return;
  companion_ = std::make_unique<AutopilotCompanion>(level_.def, rig_.loop(), rig_.loopDef().mapping, nullptr, false);
  companion_->publishTask(rig_.judging().judge());
  if (rig_.loop().running()) companion_->start();  // else startLoopWhenReady starts it with the loop
}

bool PlaySession::hint(haptics::GuideSample& out) { return companion_ && companion_->latestPlan(out) && out.valid; }

bool PlaySession::hintRing(HintRing& out) {
  return companion_ && companion_->latestHint(out) && out.kind != HintRing::None;
}

std::string PlaySession::autopilotNote() const { return companion_ ? companion_->giveUpReason() : std::string(); }

std::uint64_t PlaySession::autopilotPlans() const { return companion_ ? companion_->plans() : 0; }

autopilot::RealTimePlanCounts PlaySession::autopilotDecisions() const {
  return companion_ ? companion_->decisions() : autopilot::RealTimePlanCounts{};
}

void PlaySession::click() {
  if (stopped_ || autopilotHolds()) return;
  putProxyOnMassPoint();
  post(haptics::ServoCommandKind::Engage);
  takenHold_ = true;
  if (frozen_ != Freeze::None) holdWanted_ = true;  // frame() lets the physics run once engaged
  if (started_) startLoopWhenReady();
}

// Only while nothing is held (or the loop waits for the proxy), or while the
// physics stands still after a stop (the force is off): moving a coupled
// proxy would be a jump in the force.
void PlaySession::putProxyOnMassPoint() {
  if (!mouse_) return;
  if (frozen_ == Freeze::None && snapshot().engagement != haptics::Engagement::Disengaged &&
      snapshot().engagement != haptics::Engagement::Armed)
    return;
  const physics::Vec3 p =
      physics::massPointPosition(physics::forceStateOf(snapshot().state), level_.def.params.radius);
  const haptics::Vec3 device = (haptics::Vec3(p.x(), p.y(), p.z()) - rig_.loopDef().mapping.offset) / rig_.loopDef().mapping.scale;
  if (!device.allFinite()) return;
  mapping_.moveTo(device.x(), device.y());
  mapping_.setHeight(device.z());
  sendPointer(/*jump=*/true);
}
// Letting go while tilted left the face 0.6 s later, before the screen
// could say how to carry on (issue 27): the physics stands still instead,
// from the tick the let-go is applied, until the next take-hold.
void PlaySession::release() {
  if (autopilotHolds()) return;  // its hold is not the player's to drop: they take over first
  post(haptics::ServoCommandKind::Disengage);
  if (takenHold_ && !autopilotHolds() && rig_.loop().running()) freeze(Freeze::LetGo);
}

// A safety stop outranks the other causes: the results name it.
void PlaySession::freeze(Freeze why) {
  if (frozen_ == Freeze::None || why == Freeze::SafetyStop) frozen_ = why;
  holdWanted_ = false;
  post(haptics::ServoCommandKind::Pause);
}

void PlaySession::pause() {
  if (paused_) return;
  paused_ = true;
  post(haptics::ServoCommandKind::Pause);
  // A force device's handle is free while paused (no force holds it): the
  // hold is let go, and taken again when play goes on, where the handle is.
  if (!mouse_ && takenHold_ && !autopilotHolds() && rig_.loop().running()) {
    post(haptics::ServoCommandKind::Disengage);
    freeze(Freeze::Paused);
  }
}

void PlaySession::resume() {
  const bool faulted = fault() != haptics::SafetyFault::None;
  if (!paused_ && !faulted) return;
  paused_ = false;
  if (faulted) {
    post(haptics::ServoCommandKind::ClearFault);
    // Commands are applied at the start of a tick: by the next-but-one tick
    // from the one running now at the latest.
    faultClearedBy_ = rig_.loop().ticks() + 2;
  }
  if (frozen_ != Freeze::None) {
    // Stopped: the physics waits for the next take-hold. The autopilot,
    // holding, takes hold again itself (its hand is on its plan).
    if (autopilotHolds()) {
      post(haptics::ServoCommandKind::Engage);
      holdWanted_ = true;
    }
    return;
  }
  post(haptics::ServoCommandKind::Resume);
}

// A stop is recorded once, when a snapshot first shows it latched (and not
// one older than a ClearFault already asked for).
void PlaySession::noteStops() {
  if (snapshot().fault == haptics::SafetyFault::None) {
    stopOpen_ = false;
    return;
  }
  if (snapshot().tick <= faultClearedBy_ || stopOpen_) return;
  stopOpen_ = true;
  if (stops_.size() < 1000) stops_.push_back({snapshot().fault, snapshot().time});
  freeze(Freeze::SafetyStop);
}

void PlaySession::thawWhenHeld() {
  if (frozen_ == Freeze::None || !holdWanted_ || paused_ || fault() != haptics::SafetyFault::None) return;
  if (snapshot().engagement != haptics::Engagement::Engaged) return;
  post(haptics::ServoCommandKind::Resume);
  frozen_ = Freeze::None;
  holdWanted_ = false;
}

std::string PlaySession::stopReason() const {
  if (frozen_ == Freeze::SafetyStop && !stops_.empty())
    return std::string("safety stop: ") + haptics::safetyFaultName(stops_.back().fault);
  return "quit by the player";
}

void PlaySession::quit() { rig_.judging().fail(stopReason()); }

bool PlaySession::frame() {
  if (stopped_) return false;
  if (started_ && !startLoopWhenReady()) return true;
  rig_.drain();  // every tick judged and tapped; a judge fallen behind fails the trial
  if (companion_) companion_->publishTask(rig_.judging().judge());
  rig_.takeLatest();
  everEngaged_ = everEngaged_ || snapshot().engagement == haptics::Engagement::Engaged;
  noteStops();
  thawWhenHeld();
  handOverWhenLetGo();
  if (rig_.judging().finished()) finish();
  return !rig_.judging().finished();
}

TrialResult PlaySession::finish() {
  if (companion_) companion_->stop();
  if (!stopped_) {
    rig_.stopLoop();  // the last tick run, the replay log completed
    stopped_ = true;
  }
  if (!rig_.judging().finished()) rig_.judging().fail(stopReason());
  TrialResult result = rig_.result();
  result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - startedAt_).count();
  return result;
}

}  // namespace hemiroll::game
