#include "game/screens/PlayScreen.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "engine/physics/StateLayout.h"
#include "engine/haptics/devices/DeviceFactory.h"
#include "engine/record/ContentHash.h"
#include "engine/record/DataDirectory.h"
#include "game/app/App.h"
#include "game/trial/TrialRecording.h"
#include "game/research/ResearchSession.h"
#include "game/screens/PauseScreen.h"
#include "game/screens/ResultsScreen.h"
#include "game/screens/ScreenLayout.h"
#include "game/scores/ScoreStore.h"
#include "engine/render/Camera.h"
#include "game/trial/GhostFile.h"
#include "game/view/RenderSceneBuilder.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

PlayScreen::PlayScreen(App& app, std::string levelPath) : Screen(app), levelPath_(std::move(levelPath)) {}

PlayScreen::PlayScreen(App& app, ResearchSession& session, std::function<void(const SessionTrialEnd&)> done)
    : Screen(app), levelPath_(session.nextTrial().levelFile), research_(&session), sessionDone_(std::move(done)) {}

PlayScreen::~PlayScreen() = default;

// The session's next trial: its level with the plan's overrides, recorded
// into the session folder (rows through the judge's forward ring, drained by
// the recorder's writer thread), its replay log beside the trial's files.
void PlayScreen::beginSessionTrial(PlaySessionDef& def) {
  level_ = research_->loadNextLevel();
  const ManifestTrial& trial = research_->nextTrial();
  def.coupling = level_.def.coupling;
  def.replayFile = research_->folder() / (trial.trialId + ".replay");
  def.levelHash = trial.levelHash;
  // The player's device: its mapping and spec go into the trial's sidecar.
  haptics::ServoLoopDef loop = trialLoopDef(level_.def, def.device);
  const std::optional<haptics::DeviceSpec> spec = haptics::DeviceFactory().specOf(def.device, def.deviceOptions);
  if (!spec) throw std::runtime_error("unknown device '" + def.device + "'");
  recording_ = research_->recordNext(level_.def, loop, def.device, *spec);
  def.recordRing = &recording_->ring();
  def.recordEvery = recording_->recordEvery();
  session_ = std::make_unique<PlaySession>(level_, def);
  recording_->startWriter();
}

void PlayScreen::endSessionTrial(SessionTrialEnd end) {
  if (sessionEnded_) return;  // two Escapes in one frame: the stack changes once
  sessionEnded_ = true;
  if (end.recorded) {
    try {
      research_->finishNext(*recording_, end.result, session_->timing());
    } catch (const std::exception& e) {
      end.recorded = false;
      end.error = e.what();
    }
  }
  recording_.reset();
  app_.screens().pop();  // applied after this frame: this screen lives until then
  sessionDone_(end);
}

void PlayScreen::begin() {
  error_.clear();
  session_.reset();
  try {
    PlaySessionDef def;
    def.device = app_.settings().device;
    def.deviceOptions.joystick.index = app_.settings().joystickIndex;
    def.deviceOptions.udp.port = static_cast<std::uint16_t>(app_.settings().udpPort);
    def.requestRealtime = app_.def().requestRealtime;
    if (research_ != nullptr) {
      beginSessionTrial(def);
    } else {
      level_ = script::LevelLoader().loadFile(levelPath_);
      def.coupling = couplingFor(app_.settings(), level_.def.coupling);
      // A replay repeats the trial only on the level's own loop definition:
      // none while the player overrides the force method.
      if (!app_.settings().overrideCoupling) {
        def.replayFile = record::dataDirectory() / "replays" / "last-trial.hrr";
        def.levelHash = record::fileContentHash(levelPath_);
      }
      session_ = std::make_unique<PlaySession>(level_, def);
    }
    session_->start();
  } catch (const std::exception& e) {
    error_ = e.what();
    session_.reset();
    return;
  }
  const bool mouse = app_.settings().device == "mouse";
  hud_.reset();
  const physics::CouplingDef coupling =
      research_ != nullptr ? level_.def.coupling : couplingFor(app_.settings(), level_.def.coupling);
  // In a research session the player sees where they are in the plan.
  const std::string title = research_ == nullptr
                                ? level_.def.name
                                : "trial " + std::to_string(research_->nextTrial().index) + " of " +
                                      std::to_string(research_->trialCount()) + ": " + level_.def.name;
  hud_.setLabels(title, app_.settings().device,
                 coupling.visualOnly ? "visual only" : physics::forceMethodName(coupling.method), mouse,
                 level_.def.params.radius);
  hud_.setTakeHoldKey(app_.settings().keys.keyName(KeyAction::TakeHold));
  trace_.clear();
  lastEngagement_ = haptics::Engagement::Disengaged;
  for (const std::string& note : app_.renderer().setProps(propsOf(level_.def))) hud_.addMessage("scene: " + note, 10.0);
  loadGhost();
}

void PlayScreen::loadGhost() {
  ghost_.reset();
  scene_.ghost.shown = false;
  hud_.setGhost("");
  // No ghost in a research session's trial: it would be a condition the
  // protocol did not ask for.
  if (!app_.settings().ghost || research_ != nullptr) return;
  const std::filesystem::path file = ghostFile(record::dataDirectory(), level_.def.name, app_.settings().participant);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return;
  try {
    ghost_ = std::make_unique<ReplayPlayer>(level_.def, levelPath_, file);
  } catch (const std::exception& e) {
    hud_.setGhost(std::string("no ghost: ") + e.what());
  }
}

void PlayScreen::enter() {
  if (!started_) {
    started_ = true;
    begin();
  }
  // The menus above this screen (pause, results) need the system cursor back.
  if (session_ && session_->deviceName() == "mouse") app_.window().capturePointer(true);
}

void PlayScreen::leave() { app_.window().capturePointer(false); }

void PlayScreen::pause() {
  if (!session_ || session_->finished()) return;
  session_->pause();
  app_.screens().push(std::make_unique<PauseScreen>(app_, *this));
}

void PlayScreen::resume() {
  if (session_) session_->resume();
}

void PlayScreen::restart() {
  if (research_ == nullptr) begin();  // a session's trial is recorded once: no restart
}

void PlayScreen::quit() {
  if (session_) session_->quit();
}

void PlayScreen::input(const platform::InputEvent& e) {
  using platform::InputType;
  if (!session_) {
    if (e.type == InputType::KeyDown && (e.key == platform::Key::Escape || e.key == platform::Key::Enter)) back();
    return;
  }
  switch (e.type) {
    case InputType::PointerMove: session_->pointerMotion(e.dx, e.dy); break;
    case InputType::ButtonDown:
      if (e.button == platform::PointerButton::Left) session_->click();
      if (e.button == platform::PointerButton::Right) session_->release();
      break;
    case InputType::Wheel: session_->wheel(e.wheel); break;
    case InputType::FocusLost: pause(); break;
    case InputType::KeyDown:
      if (e.key == platform::Key::Escape && !e.repeat) pause();
      if (const std::optional<KeyAction> action = app_.settings().keys.actionOf(e.code)) keyAction(*action, e.repeat);
      break;
    default: break;
  }
}

// The keys bound in the settings (KeyBindings.h). Taking hold from the
// keyboard is how the paper's subjects did it (Sec. 4): the hand stays on
// the device. The orbit camera turns with its keys (held keys repeat): the
// mouse is the proxy's, so it cannot drag the view; strokes turn with it.
void PlayScreen::keyAction(KeyAction action, bool repeat) {
  Settings& s = app_.settings();
  constexpr double kYawStep = 0.1, kPitchStep = 0.05;  // [rad] per key press or repeat
  const bool orbit = s.camera == render::CameraMode::Orbit;
  switch (action) {
    case KeyAction::TakeHold:
      if (!repeat) session_->click();
      break;
    case KeyAction::LetGo:
      if (!repeat) session_->release();
      break;
    case KeyAction::CycleCamera:
      if (repeat) break;
      s.camera = s.camera == render::CameraMode::Follow ? render::CameraMode::Top
                 : s.camera == render::CameraMode::Top  ? render::CameraMode::Orbit
                                                        : render::CameraMode::Follow;
      app_.saveSettings();
      break;
    case KeyAction::OrbitLeft:
      if (orbit) s.orbitYaw -= kYawStep;
      break;
    case KeyAction::OrbitRight:
      if (orbit) s.orbitYaw += kYawStep;
      break;
    case KeyAction::OrbitUp:
      if (orbit) s.orbitPitch = std::min(1.5, s.orbitPitch + kPitchStep);
      break;
    case KeyAction::OrbitDown:
      if (orbit) s.orbitPitch = std::max(0.05, s.orbitPitch - kPitchStep);
      break;
  }
}

void PlayScreen::update(double dt) {
  if (!session_) return;
  session_->frame();
  for (const script::LevelMessage& m : level_.script->takeMessages()) hud_.addMessage(m.text, m.time + m.duration);
  // The score so far: the level's Lua score function twice a second (a
  // call costs microseconds; every frame would be waste, not harm).
  scoreClock_ += dt;
  if (level_.def.scoring.hasScoreFunction && scoreClock_ >= 0.5 && !session_->finished()) {
    scoreClock_ = 0.0;
    const script::ScoreResult score = level_.script->score(session_->judging().summary());
    hud_.setScore(score.score);
  }
  const haptics::ServoSnapshot& s = session_->snapshot();
  hud_.update(s, session_->judging().judge());
  const std::size_t stage = static_cast<std::size_t>(std::max(0, session_->judging().judge().stage()));
  fillFromSnapshot(level_.def, s, stage, scene_);
  if (ghost_) {
    // In step by simulated time, which stands still while paused.
    ghost_->playTo(static_cast<std::uint64_t>(std::llround(s.time / ghost_->period())));
    fillGhost(level_.def, ghost_->snapshot(), scene_.ghost);
    const double best = static_cast<double>(ghost_->ticksTotal()) * ghost_->period();
    char line[96];
    std::snprintf(line, sizeof line, ghost_->done() ? "ghost: your best finished at %.2f s" : "ghost: your best, %.2f s",
                  best);
    hud_.setGhost(line);
  }
  // The proxy is the cursor: drawn where this frame's strokes put it, not
  // where the servo thread last read it (up to a tick behind).
  const haptics::Vec3 proxy = session_->pointerScene();
  scene_.proxyPosition = {proxy.x(), proxy.y(), proxy.z()};
  if (level_.def.scene.contactTrace) {
    trace_.push(s.state[physics::force_slot::u_a], s.state[physics::force_slot::v_a], s.time);
    scene_.trace = &trace_;
  }
  scene_.camera.mode = app_.settings().camera;
  scene_.camera.zoom = app_.settings().zoom;
  scene_.camera.yaw = app_.settings().orbitYaw;
  scene_.camera.pitch = app_.settings().orbitPitch;
  session_->setScreenYaw(render::screenRightHeading(scene_.camera));

  // Sounds: clicks on taking hold and letting go; the tone while held.
  Audio& audio = app_.audio();
  if (s.engagement != lastEngagement_) {
    if (s.engagement == haptics::Engagement::Engaged) audio.play(Cue::Engage);
    if (s.engagement == haptics::Engagement::RampingOut) audio.play(Cue::Disengage);
    lastEngagement_ = s.engagement;
  }
  const double worst = session_->judging().judge().worstNormalizedMargin();
  const double closeness = !std::isfinite(worst) ? 0.0 : worst >= 0.0 ? 1.0 : 1.0 / (1.0 - worst);
  audio.setProximity(s.engagement == haptics::Engagement::Engaged ? closeness : 0.0);

  // A watchdog stopped the loop (force already off): pause and say why.
  if (session_->fault() != haptics::SafetyFault::None && !session_->finished()) {
    audio.setProximity(0.0);
    session_->pause();
    app_.screens().push(std::make_unique<PauseScreen>(
        app_, *this, std::string("safety stop: ") + haptics::safetyFaultName(session_->fault()) +
                                     ". The force is off; continue to take hold again."));
    return;
  }

  if (session_->finished()) {
    audio.setProximity(0.0);
    TrialResult result = session_->finish();
    audio.play(result.outcome == script::TrialOutcome::Success ? Cue::Success : Cue::Failure);
    if (research_ != nullptr) {
      endSessionTrial({true, std::move(result), {}});
      return;
    }
    std::string replayNote = session_->replayError();
    if (app_.settings().overrideCoupling) replayNote = "no replay: the force method was overridden in the settings";
    app_.screens().replace(std::make_unique<ResultsScreen>(app_, levelPath_, level_.def.name, std::move(result),
                                                           session_->replayFile(), replayNote));
  }
}

// Leaving a trial that could not start; a session hears why.
void PlayScreen::back() {
  if (research_ != nullptr) endSessionTrial({false, {}, error_});
  else app_.screens().pop();
}

void PlayScreen::paint() {
  if (!session_) {
    beginCentredPanel("play error", 700);
    ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "This level cannot be played:");
    ImGui::TextWrapped("%s", error_.c_str());
    if (ImGui::Button("Back  (Esc)")) back();
    ImGui::End();
    return;
  }
  const platform::PixelSize d = app_.window().drawableSize();
  app_.renderer().render(scene_, d.width, d.height);
  hud_.draw(app_.fps());
  if (!session_->waitingFor().empty()) {
    beginCentredPanel("waiting for the device", 640);
    ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "Waiting for the %s", session_->deviceName().c_str());
    ImGui::TextWrapped("%s", session_->waitingFor().c_str());
    if (session_->deviceName() == "udp")
      ImGui::TextWrapped("Start the device's bridge program, or the reference client: "
                         "hemiroll-haptic-client --port %d (docs/UDP_BRIDGE.md). The trial starts with its first state.",
                         app_.settings().udpPort);
    ImGui::TextDisabled("Esc: pause, and quit from there");
    ImGui::End();
  }
}

}  // namespace hemiroll::game
