#include "game/ui/screens/PlayScreen.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "engine/physics/StateLayout.h"
#include "engine/platform/Window.h"
#include "engine/record/DataDirectory.h"
#include "engine/render/Camera.h"
#include "engine/render/Renderer.h"
#include "game/ui/settings/Settings.h"
#include "game/ui/audio/Audio.h"
#include "game/ui/screens/FreePlay.h"
#include "game/ui/screens/PauseScreen.h"
#include "game/ui/hud/WrappedText.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenLayout.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/trial/GhostFile.h"
#include "game/ui/hud/HudLayout.h"
#include "game/ui/screens/MedalTimes.h"
#include "game/trial/DeviceProfiles.h"
#include "game/ui/view/ForceCues.h"
#include "game/ui/view/RenderSceneBuilder.h"
#include "game/trial/FaceExitForecast.h"
#include "engine/physics/StateKinematics.h"

namespace hemiroll::game {

PlayScreen::PlayScreen(ScreenHost& host, std::unique_ptr<PlayMode> mode) : Screen(host), mode_(std::move(mode)) {}

PlayScreen::PlayScreen(ScreenHost& host, std::string levelPath)
    : PlayScreen(host, std::make_unique<FreePlay>(host, std::move(levelPath))) {}

PlayScreen::~PlayScreen() = default;

void PlayScreen::begin() {
  error_.clear();
  session_.reset();
  try {
    PlaySessionDef def;
    def.device = playDeviceName(host_.settings());
    def.deviceOptions.joystick.index = host_.settings().joystickIndex;
    // A gamepad with motors but no force feedback plays when its rumble may
    // stand in for the force.
    def.deviceOptions.joystick.acceptRumble = host_.settings().rumble;
    def.deviceOptions.udp.port = static_cast<std::uint16_t>(host_.settings().udpPort);
    if (def.device == haptics::kUdpDevice && !host_.settings().deviceProfile.empty())
      useDeviceProfile(def, loadDeviceProfile(host_.settings().deviceProfile));
    def.pointer.metresPerPixel =
        std::clamp(host_.settings().mouseMmPerPixel, kMouseMmPerPixel[0], kMouseMmPerPixel[1]) * 1e-3;
    def.requestRealtime = host_.requestRealtime();
    session_ = mode_->begin(level_, def);
    session_->start();
    if (showHint_) session_->enableHints();  // kept on across restarts
  } catch (const std::exception& e) {
    error_ = e.what();
    session_.reset();
    return;
  }
  const bool mouse = haptics::isMouseDevice(session_->deviceName());
  hud_.reset();
  pulse_.clear();
  goalStage_ = -2;
  const physics::CouplingDef coupling = mode_->coupling(level_.def);
  hud_.setLabels(mode_->title(level_.def), session_->deviceName(),
                 coupling.visualOnly ? "visual only" : physics::forceMethodName(coupling.method), mouse,
                 level_.def.params.radius);
  hud_.setTakeHoldKey(host_.settings().keys.keyName(KeyAction::TakeHold));
  hud_.setTableKey(host_.settings().keys.keyName(KeyAction::HudTable));
  hud_.setPlots(level_.def.scene.plots, level_.def.params);
  trace_.clear();
  lastEngagement_ = haptics::Engagement::Disengaged;
  for (const std::string& note : host_.renderer().setProps(propsOf(level_.def))) hud_.addMessage("scene: " + note, 10.0);
  loadGhost();
}

void PlayScreen::loadGhost() {
  ghost_.reset();
  ghostTime_.reset();
  scene_.ghost.shown = false;
  hud_.setGhost("");
  if (!host_.settings().ghost || !mode_->ghostAllowed()) return;
  const std::filesystem::path file = ghostFile(record::dataDirectory(), level_.def.name, host_.settings().participant);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return;
  try {
    ghost_ = std::make_unique<ReplayPlayer>(level_.def, mode_->levelPath(), file);
    ghostTime_ = ghostTime(file);
    ghostOwner_ = ghostOwner(file);
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
  if (session_ && haptics::isMouseDevice(session_->deviceName())) host_.window().capturePointer(true);
}

void PlayScreen::leave() { host_.window().capturePointer(false); }

// Watching the autopilot, nobody steers: fewer frames leave its planner the
// CPU (measured, docs/WINDOW.md: the paper's task watched with one core
// busy won 1 of 5 at 60 fps, 5 of 5 at 30).
FrameNeed PlayScreen::frameNeed() const {
  if (!session_) return FrameNeed::Menu;
  return session_->autopilotHolds() ? FrameNeed::Watch : FrameNeed::Play;
}

void PlayScreen::pause() {
  if (!session_ || session_->finished()) return;
  silenceForceCues();
  session_->pause();
  host_.screens().push(std::make_unique<PauseScreen>(host_, *this));
}

void PlayScreen::resume() {
  if (session_) session_->resume();
}

void PlayScreen::restart() {
  if (mode_->restartAllowed()) begin();
}

void PlayScreen::watchAutopilot() {
  if (!mode_->restartAllowed()) return;
  const std::string level = mode_->levelPath();
  auto watching = std::make_unique<FreePlay>(host_, level, /*watch=*/true);
  if (const auto* free = dynamic_cast<const FreePlay*>(mode_.get())) watching->setPlaylist(free->playlist());
  mode_ = std::move(watching);
  begin();
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
      if (session_->autopilotHolds()) {  // any click while watching takes over
        session_->takeOver();
        break;
      }
      if (e.button == platform::PointerButton::Left) session_->click();
      if (e.button == platform::PointerButton::Right) session_->release();
      break;
    case InputType::Wheel: session_->wheel(e.wheel); break;
    case InputType::FocusLost: pause(); break;
    case InputType::KeyDown:
      if (e.key == platform::Key::Escape && !e.repeat) pause();
      if (const std::optional<KeyAction> action = host_.settings().keys.actionOf(e.code)) keyAction(*action, e.repeat);
      break;
    default: break;
  }
}

// The keys bound in the settings (KeyBindings.h). Taking hold from the
// keyboard is how the paper's subjects did it (Sec. 4): the hand stays on
// the device. The orbit camera turns with its keys (held keys repeat): the
// mouse is the proxy's, so it cannot drag the view; strokes turn with it.
void PlayScreen::keyAction(KeyAction action, bool repeat) {
  Settings& s = host_.settings();
  constexpr double kYawStep = 0.1, kPitchStep = 0.05;  // [rad] per key press or repeat
  const bool orbit = s.camera == render::CameraMode::Orbit;
  switch (action) {
    case KeyAction::TakeHold:
      if (repeat) break;
      if (session_->autopilotHolds())
        session_->takeOver();
      else
        session_->click();
      break;
    case KeyAction::Hint:
      if (repeat) break;
      showHint_ = !showHint_;
      if (showHint_) session_->enableHints();
      break;
    case KeyAction::HudTable:
      if (!repeat) hud_.toggleTable();
      break;
    case KeyAction::LetGo:
      if (!repeat) session_->release();
      break;
    case KeyAction::CycleCamera:
      if (repeat) break;
      s.camera = s.camera == render::CameraMode::Follow ? render::CameraMode::Top
                 : s.camera == render::CameraMode::Top  ? render::CameraMode::Orbit
                                                        : render::CameraMode::Follow;
      host_.saveSettings();
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
  for (const script::LevelMessage& m : level_.script->takeMessages())
    hud_.addMessage(withKeyNames(m.text, host_.settings().keys), m.time + m.duration);
  pollScore(dt);
  const haptics::ServoSnapshot& s = session_->snapshot();
  buildScene(s);
  hud_.update(s, session_->judging().judge());
  const platform::PixelSize window = host_.window().windowSize();
  const WindowRect hemisphere = hemisphereRect(scene_, static_cast<float>(window.width), static_cast<float>(window.height));
  hud_.setKeepClear(hemisphere);
  pulse_.setAnchor(hemisphere.x + 0.5f * hemisphere.width, hemisphere.y);
  showGoal();
  hud_.setPrompt(prompt());
  playSounds(s);
  showForceCues(s, dt);
  if (safetyStop()) return;
  if (session_->finished()) endTrial();
}

// The score so far: the level's Lua score function twice a second (a call
// costs microseconds; every frame would be waste, not harm).
void PlayScreen::pollScore(double dt) {
  scoreClock_ += dt;
  if (level_.def.scoring.hasScoreFunction && scoreClock_ >= 0.5 && !session_->finished()) {
    scoreClock_ = 0.0;
    const script::ScoreResult score = level_.script->score(session_->judging().summary());
    hud_.setScore(score.score);
  }
}

void PlayScreen::buildScene(const haptics::ServoSnapshot& s) {
  const std::size_t stage = static_cast<std::size_t>(std::max(0, session_->judging().judge().stage()));
  fillFromSnapshot(level_.def, s, stage, scene_);
  followGhost(s);
  // The proxy is the cursor: drawn where this frame's strokes put it, not
  // where the servo thread last read it (up to a tick behind).
  const haptics::Vec3 proxy = session_->pointerScene();
  scene_.proxyPosition = {proxy.x(), proxy.y(), proxy.z()};
  if (level_.def.scene.contactTrace) {
    trace_.push(s.state[physics::force_slot::u_a], s.state[physics::force_slot::v_a], s.time);
    scene_.trace = &trace_;
  }
  scene_.camera.mode = host_.settings().camera;
  scene_.camera.zoom = host_.settings().zoom;
  scene_.camera.yaw = host_.settings().orbitYaw;
  scene_.camera.pitch = host_.settings().orbitPitch;
  session_->setScreenYaw(render::screenRightHeading(scene_.camera));
  hud_.setScreenYaw(render::screenRightHeading(scene_.camera));
  inset_.update(scene_, render::screenRightHeading(scene_.camera));
  showAutopilot();
}

// The autopilot's hint (its next proxy pose, from the proxy) when the player
// asked for it, and a line in the HUD while it holds the proxy or after it
// gave up.
void PlayScreen::showAutopilot() {
  haptics::GuideSample plan;
  const bool holding = session_->autopilotHolds();
  scene_.showHint = showHint_ && !holding && session_->hint(plan);
  compass_.hide();
  HintRing ring;
  if (scene_.showHint && session_->hintRing(ring)) {
    // At a person's bandwidth (issue 26): the ring the autopilot stirs, with
    // a dot going round at its pace, or the spot it settles over; the scene
    // marks the dot (or the spot) and an arrow from the proxy to it.
    const double heading = render::screenRightHeading(scene_.camera);
    const double t = session_->snapshot().time;
    scene_.hintFrom = scene_.proxyPosition;
    if (ring.kind == HintRing::Stir) {
      const double a = ring.rate * t;
      const double pace[2] = {ring.centre[0] + ring.radius * std::cos(a), ring.centre[1] + ring.radius * std::sin(a)};
      scene_.hintTo = {pace[0], pace[1], scene_.proxyPosition[2]};
      double pr = 0.0, pu = 0.0, dr = 0.0, du = 0.0;
      toScreenDirections(scene_.proxyPosition[0] - ring.centre[0], scene_.proxyPosition[1] - ring.centre[1], heading, pr, pu);
      toScreenDirections(pace[0] - ring.centre[0], pace[1] - ring.centre[1], heading, dr, du);
      compass_.showStir(pr, pu, dr, du, ring.radius, ring.rate);
    } else {
      scene_.hintTo = {ring.point[0], ring.point[1], scene_.proxyPosition[2]};
      double right = 0.0, up = 0.0;
      toScreenDirections(ring.point[0] - scene_.proxyPosition[0], ring.point[1] - scene_.proxyPosition[1], heading, right, up);
      compass_.show(right, up, "settle");
    }
  } else if (scene_.showHint) {
    // Where the plan goes over the next moment, not only where it is: the
    // autopilot stays within a millimetre or two of the proxy, too close to
    // see; its motion is the lesson.
    constexpr double kLookAhead = 0.3;  // [s]
    scene_.hintFrom = scene_.proxyPosition;
    for (int i = 0; i < 3; ++i) scene_.hintTo[i] = plan.position[i] + kLookAhead * plan.velocity[i];
    double right = 0.0, up = 0.0;
    toScreenDirections(scene_.hintTo[0] - scene_.hintFrom[0], scene_.hintTo[1] - scene_.hintFrom[1],
                       render::screenRightHeading(scene_.camera), right, up);
    compass_.show(right, up);
  }
  const std::string note = session_->autopilotNote();
  const std::string takeHold = host_.settings().keys.keyName(KeyAction::TakeHold);
  if (holding)
    hud_.setAutopilot(note.empty() ? "AUTOPILOT playing: click or " + takeHold + " to take over" : note);
  else if (showHint_)
    hud_.setAutopilot(note.empty() ? "hint (" + host_.settings().keys.keyName(KeyAction::Hint) +
                                         "): circle round the green ring at the green dot's pace; settle on the green spot"
                                   : note);
  else
    hud_.setAutopilot("");
}

// The task's short form for the stage the judge is on: on screen all along
// (the level's own texts come and go).
void PlayScreen::showGoal() {
  const task::TaskJudge& judge = session_->judging().judge();
  const int stage = judge.stage();
  if (stage == goalStage_) return;
  goalStage_ = stage;
  const task::StageDef* current = judge.currentStage();
  const int count = static_cast<int>(judge.task().stages.size());
  hud_.setGoal(current ? taskGoal(*current, stage, count)
                       : judge.task().watchOnly() ? "Watch: the level plays itself" : "");
}

// What the player must do now, if anything: take hold to start (the clock
// waits), or take hold again after letting go or a stop (the physics waits:
// the mass point does not slide off the face meanwhile).
std::string PlayScreen::prompt() const {
  if (session_->autopilotHolds() || session_->finished() || !session_->waitingFor().empty()) return "";
  const std::string key = host_.settings().keys.keyName(KeyAction::TakeHold);
  const std::string how = haptics::isMouseDevice(session_->deviceName()) ? "Click or press " + key : "Press " + key;
  if (session_->awaitingTakeHold()) return how + " to take hold\nthe clock starts then";
  const bool armed = session_->snapshot().engagement == haptics::Engagement::Armed;
  switch (session_->frozen()) {
    case Freeze::None: break;
    case Freeze::LetGo:
      if (armed) return "Bring the handle onto the mass point\nto take hold again";
      return "You let go: the hemisphere waits.\n" + how + " to take hold again";
    case Freeze::Paused:
      if (armed) return "Bring the handle onto the mass point\nto take hold again";
      return "The hemisphere waits.\n" + how + " to take hold again";
    case Freeze::SafetyStop: {
      const std::string what = session_->stops().empty()
                                   ? std::string("safety stop")
                                   : std::string("Safety stop: ") + haptics::safetyFaultName(session_->stops().back().fault);
      if (armed) return what + ".\nBring the handle onto the mass point to go on";
      return what + ".\nThe hemisphere waits: " + how + " to take hold again";
    }
  }
  if (session_->letGo()) return "You let go: " + how + "\nto take hold again";
  return "";
}

void PlayScreen::followGhost(const haptics::ServoSnapshot& s) {
  if (!ghost_) return;
  // In step by simulated time, which stands still while paused.
  ghost_->playTo(static_cast<std::uint64_t>(std::llround(s.time / ghost_->period())));
  fillGhost(level_.def, ghost_->snapshot(), scene_.ghost);
  // The judged time kept with the ghost: the results screen's number. (The
  // log runs a few ticks past the judge's end; an older ghost without its
  // time is timed by its length.)
  const double best = ghostTime_.value_or(static_cast<double>(ghost_->ticksTotal()) * ghost_->period());
  const bool finished = ghostTime_ ? s.time >= *ghostTime_ : ghost_->done();
  // Whose run it is: the player's best, or the autopilot's line they chose to race.
  const bool autopilot = ghostOwner_ == GhostOwner::Autopilot;
  char line[96];
  if (finished)
    std::snprintf(line, sizeof line, autopilot ? "ghost: the autopilot's line finished at %.2f s"
                                               : "ghost: your best finished at %.2f s", best);
  else
    std::snprintf(line, sizeof line, autopilot ? "ghost: the autopilot's line, %.2f s" : "ghost: your best, %.2f s",
                  best);
  hud_.setGhost(line);
}

// Clicks on taking hold and letting go; the tone while held, higher the
// closer the worst tolerance is to being met.
void PlayScreen::playSounds(const haptics::ServoSnapshot& s) {
  Audio& audio = host_.audio();
  if (s.engagement != lastEngagement_) {
    if (s.engagement == haptics::Engagement::Engaged) audio.play(Cue::Engage);
    if (s.engagement == haptics::Engagement::RampingOut) audio.play(Cue::Disengage);
    lastEngagement_ = s.engagement;
  }
  const double worst = session_->judging().judge().worstNormalizedMargin();
  const double closeness = !std::isfinite(worst) ? 0.0 : worst >= 0.0 ? 1.0 : 1.0 / (1.0 - worst);
  audio.setProximity(s.engagement == haptics::Engagement::Engaged ? closeness : 0.0);
}

// The substitutes for the force a mouse cannot render (issue 26), each as
// the settings have it: the strain ring round the proxy, the force tone,
// rumble on a joystick with motors, and the pulse before the mass point
// leaves the face (FaceExitForecast on the latest state, while the physics
// runs with the proxy held).
void PlayScreen::showForceCues(const haptics::ServoSnapshot& s, double dt) {
  const Settings& settings = host_.settings();
  const bool held = s.engagement == haptics::Engagement::Engaged && !session_->paused() &&
                    session_->frozen() == Freeze::None && !session_->autopilotHolds();
  const physics::HemisphereParams& params = level_.def.params;
  const double force = std::sqrt(s.handForce[0] * s.handForce[0] + s.handForce[1] * s.handForce[1] +
                                 s.handForce[2] * s.handForce[2]);
  const double strain = couplingStrain(force, params.pointMass, params.gravity);
  scene_.showProxyRing = settings.strainRing && scene_.springOn;
  if (scene_.showProxyRing) {
    const StrainRing ring = strainRing(strain, params.radius);
    scene_.proxyRingRadius = ring.radius;
    scene_.proxyRingColour = ring.colour;
  }
  host_.audio().setForceTone(settings.forceTone && held ? strain : -1.0);
  if (settings.rumble) session_->rumble(held ? strainRumble(strain) : 0.0);
  const physics::ForceDrivenState x = physics::forceStateOf(s.state);
  const physics::Vec3 onPoint(s.handForce[0], s.handForce[1], s.handForce[2]);
  const bool warn = settings.fallWarning && held &&
                    forecastFaceExit(x, params.radius, faceAcceleration(x, params, onPoint)).warn;
  pulse_.update(warn, dt);
}

void PlayScreen::silenceForceCues() {
  host_.audio().setForceTone(-1.0);
  if (session_) session_->rumble(0.0);
  pulse_.clear();
}

// A watchdog stopped the loop (force already off, the physics standing
// still): pause and say why, and how to go on.
bool PlayScreen::safetyStop() {
  if (session_->fault() == haptics::SafetyFault::None || session_->finished()) return false;
  host_.audio().setProximity(0.0);
  silenceForceCues();
  session_->pause();
  const std::string key = host_.settings().keys.keyName(KeyAction::TakeHold);
  host_.screens().push(std::make_unique<PauseScreen>(
      host_, *this,
      std::string("Safety stop: ") + haptics::safetyFaultName(session_->fault()) +
          ". The force is off and the hemisphere waits where it is. Continue, then take hold again (" +
          (haptics::isMouseDevice(session_->deviceName()) ? "click or " + key : key) + ") to play on."));
  return true;
}

void PlayScreen::endTrial() {
  host_.audio().setProximity(0.0);
  silenceForceCues();
  TrialResult result = session_->finish();
  host_.audio().play(result.outcome == task::TrialOutcome::Success ? Cue::Success : Cue::Failure);
  // The last frame stays on screen behind the results, with what decided it
  // and what the loop's timing did to it.
  TrialEnding ending = TrialEnding::of(scene_, scene_.trace);
  ending.decidedBy = explainEnding(result, session_->judging().judge().task(), render::screenRightHeading(scene_.camera));
  LoopStory story;
  const haptics::ServoSnapshot& last = session_->snapshot();
  story.forceOutput = session_->device().spec().hasForceOutput;
  story.stalls = last.stalls;
  story.worstLateness = last.maxLateness;
  story.slowedBy = static_cast<double>(last.missedTicks) * 1e-3;
  for (const SafetyStop& stop : session_->stops()) story.stops.push_back({haptics::safetyFaultName(stop.fault), stop.time});
  for (std::string& line : explainLoop(story)) ending.decidedBy.push_back(std::move(line));
  ending.scoring = level_.def.scoring;
  ending.medalTimes = medalTimes(level_);
  mode_->finished(*session_, std::move(result), level_.def, std::move(ending));
}

// Leaving a trial that could not start; a session hears why.
void PlayScreen::back() { mode_->leftWithoutTrial(error_); }

void PlayScreen::paint() {
  if (!session_) {
    beginCentredPanel("play error", 700);
    ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "This level cannot be played:");
    wrappedText(error_);
    if (ImGui::Button("Back  (Esc)")) back();
    ImGui::End();
    return;
  }
  const platform::PixelSize d = host_.window().drawableSize();
  host_.renderer().render(scene_, d.width, d.height);
  hud_.draw(host_.fps());
  compass_.draw(&hud_.windowRects());
  inset_.draw(&hud_.windowRects());
  pulse_.draw();
  if (!session_->waitingFor().empty()) {
    beginCentredPanel("waiting for the device", 640);
    ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "Waiting for the %s", session_->deviceName().c_str());
    wrappedText(session_->waitingFor());
    if (session_->deviceName() == haptics::kUdpDevice)
      wrappedTextf("Start the device's bridge program, or the reference client: "
                   "hemiroll-haptic-client --port %d (docs/UDP_BRIDGE.md). The trial starts with its first state.",
                   host_.settings().udpPort);
    ImGui::TextDisabled("Esc: pause, and quit from there");
    ImGui::End();
  }
}

}  // namespace hemiroll::game
