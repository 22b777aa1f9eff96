#pragma once
// A human playing a level in real time: a TrialRig (the loop, judge and
// record tap a bot's trial has) driven by its threaded driver, with a
// person's device instead of a bot: the mouse (MouseDevice), a
// force-feedback joystick (SdlJoystickDevice) or a haptic device behind the
// UDP bridge (UdpBridgeDevice), made by haptics::DeviceFactory. What is
// here is what is about the person: the pointer, taking hold and letting
// go, stops and pauses, the autopilot's takeover.
//   servo thread:  device (its latest sample, lock-free) ->
//                  coupling -> physics -> safety -> snapshot + a RecordRow
//                  of every tick into the rig's lock-free ring;
//   UI thread:     mouse only: pointer motion -> PointerMapping ->
//                  MouseDevice (the proxy moves by the mouse's strokes,
//                  turned with the camera: PointerMapping.h says why not by
//                  its place);
//                  once per frame: the rig drains the ring (every tick
//                  judged and tapped, level callbacks at their rate), latest
//                  snapshot for the renderer and the HUD.
// frame() never waits for the servo loop. A safety fault (a watchdog: the
// loop starved a force device, stale input) does not end the trial: the
// loop has already taken the force off and stopped; fault() says which, and
// stops() keeps each with its time. Engagement follows the loop's rule: a
// click (or a key) arms it, and it engages when the proxy reaches the mass
// point; the force then ramps in (ServoSnapshot::rampScale).
//
// Stops that fit the device (issue 27): a device without force output (the
// mouse) has no force to hold while its loop runs late, so its loop is not
// stopped by a late tick (ForceSafety) and catches up to
// kForcelessCatchUpTicks (TrialRig), then slows its clock (ServoLoop); a device that
// renders force keeps every watchdog. After any stop - a safety stop, the
// player letting go, a pause with a force device (its handle is free while
// paused) - the physics stands still (frozen()) until the player takes hold
// again: the mass point does not slide off the face while the screen says
// how to go on. Quitting while stopped ends the trial naming the stop.
//
// A device that is open but not yet delivering (the bridge before its
// client's first state) holds the start: the loop starts, and the trial's
// clock with it, at the first frame() that finds the device ready, and
// waitingFor() says what it waits for meanwhile.
//
// Taking hold (a person's trial): the clock starts when the player first
// takes hold, not while they read the level's text (awaitingTakeHold()
// until then; the level's on_start has run, the physics stands still). With
// the mouse, taking hold always works: the proxy is put on the mass point
// first (wherever the pointer wandered), so that it engages at once and the
// force ramps in; a force device's handle must be brought there by hand.

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "engine/haptics/devices/MouseDevice.h"
#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "engine/haptics/PointerMapping.h"
#include "engine/haptics/ServoLoop.h"
#include "game/play/AutopilotCompanion.h"
#include "game/play/TakeoverDevice.h"
#include "engine/task/DeviceProfileDef.h"
#include "game/trial/TrialJudge.h"
#include "game/trial/TrialRig.h"

namespace hemiroll::game {

// The CPU one call of a level's on_update may take in the window: a frame
// at 60 Hz (the judge runs the callbacks of a frame's ticks once per frame).
inline constexpr double kWindowLuaTickSeconds = 1.0 / 60.0;

// Why the physics stands still until the player takes hold again.
enum class Freeze { None, LetGo, SafetyStop, Paused };

// A safety stop: which watchdog, at what simulated time [s].
struct SafetyStop {
  haptics::SafetyFault fault = haptics::SafetyFault::None;
  double time = 0.0;
};

struct PlaySessionDef {
  std::string device = haptics::kMouseDevice;        // "mouse", "joystick" or "udp" (DeviceFactory names)
  haptics::DeviceOptions deviceOptions;  // the joystick's index, the bridge's port, ...
  haptics::PointerMappingDef pointer;
  bool requestRealtime = true;         // SCHED_FIFO for the servo thread when permitted
  haptics::ServoClock* clock = nullptr;  // the servo thread's clock; null = the real one (tests stall it)
  std::optional<physics::CouplingDef> coupling;  // the player's settings; none = the level's
  std::optional<haptics::SafetyDef> safety;      // the loop's limits and watchdogs; none = the defaults
  // Log the trial for a replay here ("" = no replay); levelHash goes into
  // its header (record::fileContentHash of the level file).
  std::filesystem::path replayFile;
  std::string levelHash;
  // The autopilot beside the player (AutopilotCompanion, on its own thread):
  // watchAutopilot: it holds the proxy until takeOver(); guidance: its plan
  // pulls the player's device (Guidance.h; felt only on a device with force
  // output). Either way, and after enableHints(), hint() offers its plan.
  bool watchAutopilot = false;
  haptics::GuidanceDef guidance;
  // The physics and the clock wait for the player's first take-hold
  // (ignored while the autopilot holds: it takes hold at once).
  bool clockStartsOnTakeHold = true;
  // The force device's profile (useDeviceProfile): a level whose coupling it
  // cannot render is refused by the constructor, in one sentence naming both.
  std::optional<task::DeviceProfileDef> profile;
};

// Holds a device behind the bridge to `profile`: the bridge's spec (the
// clamp, the stiffest coupling) and the safety layer's limits (DeviceProfiles.h).
void useDeviceProfile(PlaySessionDef& def, const task::DeviceProfileDef& profile);

class PlaySession {
 public:
  // `level` must outlive the session. Throws std::invalid_argument for a
  // level the loop refuses (its message names the field), and
  // std::runtime_error "<device>: <why>" for a device that cannot be opened.
  // Constructed on the thread that owns SDL (the joystick opens there).
  PlaySession(script::LoadedLevel& level, const PlaySessionDef& def);
  ~PlaySession();

  // Its loop definition (for a recording's sidecar) and record tap (a
  // research session's trial: TrialRecording::tap), before start().
  const haptics::ServoLoopDef& loopDef() const { return rig_.loopDef(); }
  void record(const RecordTap& tap) { rig_.record(tap); }

  void start();  // on_start, then the servo thread (once the device is ready)
  // "" once the loop runs, else what the start waits for (a sentence).
  const std::string& waitingFor() const { return waitingFor_; }
  // The device is ready and the trial waits for the player's first take-hold.
  bool awaitingTakeHold() const { return judgeStarted_ && !takenHold_ && holdsClock() && !rig_.judging().finished(); }
  // The player has held the proxy and let go since (the trial goes on:
  // taking hold again is how to carry on).
  bool letGo() const { return everEngaged_ && snapshot().engagement == haptics::Engagement::Disengaged; }
  // The physics stands still until the player takes hold again, and why.
  Freeze frozen() const { return frozen_; }
  // Every safety stop of this trial, in order.
  const std::vector<SafetyStop>& stops() const { return stops_; }
  const std::string& deviceName() const { return deviceName_; }
  // The mouse with the hand feel ("mouse-hand"): the proxy is the simulated
  // hand, not the pointer.
  bool handFeel() const { return deviceName_ == haptics::kMouseHandDevice; }
  // UI thread: rumble the player's joystick at `strength` in [0, 1] (0
  // stops it); false when the device has no motors to rumble (not a
  // joystick, or SDL says it has none).
  bool rumble(double strength);
  const haptics::HapticDevice& device() const { return *player_; }
  // UI thread, mouse only (ignored for other devices): the pointer moved by
  // (dx, dy) [window px].
  void pointerMotion(double dx, double dy);
  // The heading of screen right [rad] (render::screenRightHeading of the camera).
  void setScreenYaw(double radians) { mapping_.setScreenYaw(radians); }
  void wheel(double notches);
  // Take hold: arm the engagement (the loop engages near the mass point);
  // the mouse's proxy is put on the mass point first. The first take-hold
  // starts the clock; after a stop, the physics runs again once engaged.
  void click();
  void release();      // let go: the force ramps out, the physics stands still
  // Physics stops, force zero at once; with a force device the hold is let
  // go too (the handle is free while paused).
  void pause();
  // Ends the player's pause; clears a latched safety fault. The physics runs
  // again at once unless a stop froze it (then at the next take-hold; while
  // the autopilot holds, it takes hold again itself).
  void resume();
  // The latched fault of the latest snapshot; None once resume() asked to
  // clear it (snapshots older than the clearing tick still show it).
  haptics::SafetyFault fault() const {
    return snapshot().tick <= faultClearedBy_ ? haptics::SafetyFault::None : snapshot().fault;
  }
  // Ends the trial as a failure: "quit by the player", or while stopped
  // for safety, "safety stop: <what>".
  void quit();

  // Once per frame: judge what the loop produced; returns true while running.
  bool frame();
  const haptics::ServoSnapshot& snapshot() const { return rig_.snapshot(); }
  const TrialJudge& judging() const { return rig_.judging(); }
  bool paused() const { return paused_; }
  bool finished() const { return rig_.judging().finished(); }
  // Stops the loop (idempotent) and returns the result.
  TrialResult finish();
  haptics::LoopTimingSummary timing() const { return rig_.loop().timingSummary(); }
  const char* realtimeNote() const { return rig_.loop().realtime().note; }
  // After finish(): the replay log when one was asked for and came out
  // usable, else "" (replayError() says why).
  std::filesystem::path replayFile() const { return rig_.replayFile(); }
  const std::string& replayError() const { return rig_.replayError(); }
  // Where the pointer has put the proxy now, scene frame [m] (what the game
  // draws in place of the system cursor). While the autopilot holds, where it
  // does; with the hand feel, where the simulated hand is (the loop's latest).
  haptics::Vec3 pointerScene() const;

  // Watching the autopilot: true until the player takes over.
  bool autopilotHolds() const { return takeover_ && !takeover_->playerHolds(); }
  // Whether the autopilot held the proxy at any time of this trial (its
  // result is then not the player's: no best, no ghost).
  bool assisted() const { return takeover_ != nullptr; }
  // The player takes the proxy from the autopilot (UI thread): the mouse
  // carries on from where the autopilot left the proxy; for any other device
  // the autopilot lets go (the force ramps out), the device is handed over
  // once disengaged, and the player's click takes hold with the usual ramp.
  void takeOver();
  // Starts the autopilot beside the player for hints, if it is not already
  // planning (UI thread; its planning costs CPU, so only once asked for).
  void enableHints();
  // The autopilot's latest plan (false when it has none: no companion, not
  // yet, or it gave up); its give-up reason ("" while it plans).
  bool hint(haptics::GuideSample& out);
  // The same plan as a ring to trace or a spot to settle over (HintRing).
  bool hintRing(HintRing& out);
  std::string autopilotNote() const;
  std::uint64_t autopilotPlans() const;
  autopilot::RealTimePlanCounts autopilotDecisions() const;

 private:
  std::unique_ptr<haptics::HapticDevice> makeDevice(const PlaySessionDef& def, const haptics::ServoLoopDef& loop);
  void post(haptics::ServoCommandKind kind) { rig_.post(kind); }  // a full ring drops it; the player clicks again
  void sendPointer(bool jump);
  void handOverWhenLetGo();
  bool startLoopWhenReady();
  bool holdsClock() const { return clockStartsOnTakeHold_ && !takeover_; }
  void putProxyOnMassPoint();
  void freeze(Freeze why);
  std::string stopReason() const;  // what quitting now ends the trial with
  void noteStops();
  void thawWhenHeld();

  script::LoadedLevel& level_;
  haptics::PointerMapping mapping_;
  std::string deviceName_;
  // The rig owns the devices; these name its parts (set while it is built,
  // so declared before it).
  haptics::HapticDevice* player_ = nullptr;  // the person's device
  haptics::MouseDevice* mouse_ = nullptr;    // player_ when it is the mouse
  haptics::SdlJoystickDevice* joystick_ = nullptr;  // player_ when it is the joystick
  // Watching: the autopilot's hand and the switch between it and player_.
  HandoffBotDevice* autopilotHand_ = nullptr;
  TakeoverDevice* takeover_ = nullptr;
  TrialRig rig_;
  std::unique_ptr<AutopilotCompanion> companion_;  // after rig_: stopped before its loop
  std::string waitingFor_;
  bool paused_ = false, stopped_ = false, started_ = false;
  bool clockStartsOnTakeHold_ = true;
  bool judgeStarted_ = false;  // on_start has run (the device was ready)
  bool takenHold_ = false;     // the player has taken hold at least once
  bool everEngaged_ = false;   // a snapshot has shown the proxy engaged
  bool handoverPending_ = false;  // a force device's takeover waits for the autopilot to let go
  std::uint64_t faultClearedBy_ = 0;  // the tick by which a ClearFault has been applied
  Freeze frozen_ = Freeze::None;
  bool holdWanted_ = false;           // frozen, and a take-hold was asked for: run once engaged
  bool stopOpen_ = false;             // the latest stop is still latched (not yet recorded again)
  std::vector<SafetyStop> stops_;
  std::chrono::steady_clock::time_point startedAt_;
};

}  // namespace hemiroll::game
