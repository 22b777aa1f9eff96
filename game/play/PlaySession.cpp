#include "game/play/PlaySession.h"

#include <algorithm>

#include "engine/physics/StateKinematics.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

PlaySession::PlaySession(script::LoadedLevel& level, const PlaySessionDef& def)
    : level_(level),
      loopDef_(trialLoopDef(level.def, def.device)),
      mapping_(def.pointer),
      ring_(std::make_unique<haptics::RecordRing>()),
      deviceName_(def.device),
      judging_(level, def.recordRing, def.recordEvery, /*faultsEndTrial=*/false) {
  if (def.device == "mouse") {
    auto mouse = std::make_unique<haptics::MouseDevice>(def.deviceOptions.mouse);
    mouse_ = mouse.get();
    device_ = std::move(mouse);
  } else {
    haptics::DeviceChoice choice = haptics::DeviceFactory().makeAndOpen(def.device, def.deviceOptions);
    if (!choice.device) throw std::runtime_error(def.device + ": " + choice.error);
    device_ = std::move(choice.device);
  }
  clockStartsOnTakeHold_ = def.clockStartsOnTakeHold;
  // Nothing to hold still on a device without force: a stall is caught up
  // (then the clock slows) instead of stopping the game (ForceSafety).
  if (!device_->spec().hasForceOutput) loopDef_.maxCatchUpTicks = kForcelessCatchUpTicks;
  loopDef_.requestRealtime = def.requestRealtime;
  loopDef_.clock = def.clock;
  loopDef_.recordRing = ring_.get();
  loopDef_.recordEvery = 1;  // the judge sees every tick
  if (def.coupling) loopDef_.coupling = *def.coupling;
  if (def.safety) loopDef_.safety = *def.safety;
  if (!def.replayFile.empty()) {
    try {
      capture_ = std::make_unique<ReplayCapture>(def.replayFile, def.levelHash, loopDef_.period, def.device);
      capture_->attach(loopDef_);
    } catch (const std::exception& e) {
      capture_.reset();
      replayError_ = e.what();  // the trial goes on without a replay
    }
  }
  loopDef_.guidance = def.guidance;
  if (def.watchAutopilot) {
    autopilotHand_ = std::make_unique<HandoffBotDevice>(device_->spec(), loopDef_.mapping);
    takeover_ = std::make_unique<TakeoverDevice>(*autopilotHand_, *device_);
  }
  loop_ = std::make_unique<haptics::ServoLoop>(loopDef_, takeover_ ? static_cast<haptics::HapticDevice&>(*takeover_)
                                                                   : *device_);
  if (def.watchAutopilot || def.guidance.active())
    companion_ = std::make_unique<AutopilotCompanion>(level.def, *loop_, loopDef_.mapping, autopilotHand_.get(),
                                                      def.guidance.active());
  initial_ = physics::forceStateOf(loopDef_.initialState);
  snapshot_.state = loopDef_.initialState;
  if (mouse_) {
    // The proxy starts on the mass point (the device origin is mapped to
    // where a level's mass point starts, at its height), so that a click
    // takes hold at once, without aiming or touching the wheel.
    const physics::Vec3 p = physics::massPointPosition(initial_, level.def.params.radius);
    const double zDevice = (p.z() - loopDef_.mapping.offset.z()) / loopDef_.mapping.scale;
    mapping_.wheel(zDevice / mapping_.def().wheelStep);
    sendPointer(/*jump=*/true);
  }
}

PlaySession::~PlaySession() {
  if (companion_) companion_->stop();
  if (!stopped_) loop_->stop();
  device_->close();  // on this (the SDL) thread, after the loop let go of it
}

void PlaySession::start() {
  started_ = true;
  startedAt_ = std::chrono::steady_clock::now();
  startLoopWhenReady();
}

// The bridge says "no client yet" until its first good state; starting the
// loop before that would trip its watchdog at once.
bool PlaySession::startLoopWhenReady() {
  if (loop_->running() || stopped_) return true;
  if (!device_->ready()) {
    const char* why = device_->error();
    waitingFor_ = deviceName_ + ": " + (why ? why : "not ready");
    return false;
  }
  waitingFor_.clear();
  if (!judgeStarted_) {
    judgeStarted_ = true;
    // The level's callbacks run on the window's thread, once per frame for
    // the ticks it drains: each on_update has a frame's CPU as its deadline.
    level_.script->setTiming({.realtime = true, .tickSeconds = kWindowLuaTickSeconds});
    judging_.start(initial_);
  }
  if (judging_.finished()) return true;   // on_start ended it
  if (holdsClock() && !takenHold_) return false;
  startedAt_ = std::chrono::steady_clock::now();
  if (capture_) capture_->start();
  if (autopilotHolds()) {
    // The autopilot's hand rests on the mass point until its first plan
    // lands (a few ms on its own thread; without this pose the loop would
    // read a device with nothing to say), and takes hold at once.
    autopilotHand_->publish(loopDef_.startTime, physics::massPointPosition(initial_, level_.def.params.radius),
                            haptics::Vec3::Zero());
    post(haptics::ServoCommandKind::Engage);
  }
  loop_->start();
  if (companion_) {
    companion_->publishTask(judging_.judge());  // the goal before the first plan
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

haptics::Vec3 PlaySession::pointerScene() const {
  if (autopilotHolds()) {
    const haptics::Triple& p = snapshot_.proxyPosition;
    return {p[0], p[1], p[2]};
  }
  return loopDef_.mapping.positionToScene(mapping_.position());
}

void PlaySession::takeOver() {
  if (!autopilotHolds() || handoverPending_) return;
  if (mouse_) {
    companion_->stopDriving();
    // The pointer picks the proxy up where the autopilot left it: no jump,
    // no gap in the coupling.
    const haptics::Triple& p = snapshot_.proxyPosition;
    const haptics::Vec3 device = (haptics::Vec3(p[0], p[1], p[2]) - loopDef_.mapping.offset) / loopDef_.mapping.scale;
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
  if (!handoverPending_ || snapshot_.engagement != haptics::Engagement::Disengaged) return;
  companion_->stopDriving();
  takeover_->handToPlayer();
  handoverPending_ = false;
}

void PlaySession::enableHints() {
  if (companion_ || stopped_) return;
  companion_ = std::make_unique<AutopilotCompanion>(level_.def, *loop_, loopDef_.mapping, nullptr, false);
  companion_->publishTask(judging_.judge());
  if (loop_->running()) companion_->start();  // else startLoopWhenReady starts it with the loop
}

bool PlaySession::hint(haptics::GuideSample& out) { return companion_ && companion_->latestPlan(out) && out.valid; }

bool PlaySession::hintRing(HintRing& out) {
  return companion_ && companion_->latestHint(out) && out.kind != HintRing::None;
}

std::string PlaySession::autopilotNote() const { return companion_ ? companion_->giveUpReason() : std::string(); }

std::uint64_t PlaySession::autopilotPlans() const { return companion_ ? companion_->plans() : 0; }

void PlaySession::post(haptics::ServoCommandKind kind) {
  haptics::ServoCommand c;
  c.kind = kind;
  loop_->post(c);  // a full ring (64 commands) drops it; the player clicks again
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
  if (frozen_ == Freeze::None && snapshot_.engagement != haptics::Engagement::Disengaged &&
      snapshot_.engagement != haptics::Engagement::Armed)
    return;
  const physics::Vec3 p =
      physics::massPointPosition(physics::forceStateOf(snapshot_.state), level_.def.params.radius);
  const haptics::Vec3 device = (haptics::Vec3(p.x(), p.y(), p.z()) - loopDef_.mapping.offset) / loopDef_.mapping.scale;
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
  if (takenHold_ && !autopilotHolds() && loop_->running()) freeze(Freeze::LetGo);
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
  if (!mouse_ && takenHold_ && !autopilotHolds() && loop_->running()) {
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
    faultClearedBy_ = loop_->ticks() + 2;
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
  if (snapshot_.fault == haptics::SafetyFault::None) {
    stopOpen_ = false;
    return;
  }
  if (snapshot_.tick <= faultClearedBy_ || stopOpen_) return;
  stopOpen_ = true;
  if (stops_.size() < 1000) stops_.push_back({snapshot_.fault, snapshot_.time});
  freeze(Freeze::SafetyStop);
}

void PlaySession::thawWhenHeld() {
  if (frozen_ == Freeze::None || !holdWanted_ || paused_ || fault() != haptics::SafetyFault::None) return;
  if (snapshot_.engagement != haptics::Engagement::Engaged) return;
  post(haptics::ServoCommandKind::Resume);
  frozen_ = Freeze::None;
  holdWanted_ = false;
}

std::string PlaySession::stopReason() const {
  if (frozen_ == Freeze::SafetyStop && !stops_.empty())
    return std::string("safety stop: ") + haptics::safetyFaultName(stops_.back().fault);
  return "quit by the player";
}

void PlaySession::quit() { judging_.fail(stopReason()); }

bool PlaySession::frame() {
  if (stopped_) return false;
  if (started_ && !startLoopWhenReady()) return true;
  judging_.drain(*ring_);
  if (companion_) companion_->publishTask(judging_.judge());
  if (!judging_.finished() && loop_->recordDropped() > 0)
    judging_.fail("the judge fell behind the servo loop (ticks dropped)");
  loop_->latest(snapshot_);
  everEngaged_ = everEngaged_ || snapshot_.engagement == haptics::Engagement::Engaged;
  noteStops();
  thawWhenHeld();
  handOverWhenLetGo();
  if (judging_.finished()) finish();
  return !judging_.finished();
}

TrialResult PlaySession::finish() {
  if (companion_) companion_->stop();
  if (!stopped_) {
    loop_->stop();
    stopped_ = true;
    loop_->latest(snapshot_);  // the last tick run
    if (capture_) replayError_ = capture_->finish(loop_->inputDropped());
  }
  if (!judging_.finished()) judging_.fail(stopReason());
  TrialResult result = judging_.result(initial_);
  result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - startedAt_).count();
  return result;
}

}  // namespace hemiroll::game
