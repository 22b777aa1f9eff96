#include "game/trial/BotTrial.h"

#include <cmath>

#include "engine/haptics/ServoClock.h"
#include "engine/physics/StateKinematics.h"
#include "engine/script/ScriptError.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/BotDevice.h"
#include "game/trial/HandoffBotDevice.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

namespace {

TrialRigDef rigDefOf(const TrialSettings& settings) {
  TrialRigDef def;
  def.guidance = settings.guidance;
  def.safety = settings.safety;
  def.threaded = settings.realtime;
  def.requestRealtime = settings.realtime;
  return def;
}

}  // namespace

BotTrial::BotTrial(script::LoadedLevel& level, script::BotPolicy& bot, const TrialSettings& settings)
    : level_(level),
      bot_(bot),
      settings_(settings),
      rig_(level, rigDefOf(settings),
           [this](const haptics::ServoLoopDef& loop) -> std::unique_ptr<haptics::HapticDevice> {
             if (settings_.realtime) {
               auto device = std::make_unique<HandoffBotDevice>(settings_.device, loop.mapping);
               handoff_ = device.get();
               return device;
             }
             auto device = std::make_unique<BotDevice>(settings_.device, loop.mapping, loop.period);
             botDevice_ = device.get();
             return device;
           }),
      observer_(level.def.params, rig_.loopDef().mapping) {}

BotTrial::~BotTrial() = default;

TrialResult BotTrial::run() {
  wallStart_ = std::chrono::steady_clock::now();
  if (settings_.realtime)
    runThreaded();
  else
    runStepping();
  TrialResult result = rig_.result();
  result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
  return result;
}

// The bot's (and the guide's) init, and the level's on_start. `timing`
// bounds each call's CPU (TrialTiming.h).
void BotTrial::begin(const script::TrialTiming& timing) {
  TrialJudge& judging = rig_.judging();
  rig_.post(haptics::ServoCommandKind::Engage);
  bot_.setTiming(timing);
  level_.script->setTiming(timing);
  const script::BotLevelInfo info = botLevelInfo(level_.def, rig_.loopDef(), settings_.device);
  script::BotLevelInfo placed = info;
  placed.place = settings_.place;
  placed.memory = settings_.memory;
  try {
    bot_.init(placed, settings_.seed);
  } catch (const script::ScriptError& e) {
    judging.judge().finish(task::TrialOutcome::Failure, std::string("bot error: ") + e.what(), rig_.loop().time());
  }
  judging.start(rig_.initial());  // on_start, and on_fail for a failed init
  if (!settings_.guidance.active()) return;
  AutopilotBotOptions guiding;
  guiding.plannerThread = settings_.realtime;  // plans beside the bot's thread, as a real-time autopilot bot does
  guiding.holdsProxy = false;  // the bot's hand holds the proxy; the plan only guides it
  guide_ = std::make_unique<AutopilotBot>(guiding);
  guide_->setTiming(timing);
  try {
    guide_->init(info, static_cast<std::int64_t>(settings_.seed));
  } catch (const script::ScriptError& e) {
    judging.fail(std::string("guidance: ") + e.what());
  }
}

// One bot call on the loop's state at `time`: the pose goes to the bot's
// device, the guide's plan to the loop. False when the bot failed or gave
// up (the trial is then finished).
bool BotTrial::answer(double time, const physics::ForceDrivenState& state) {
  TrialJudge& judging = rig_.judging();
  observer_.fill(time, state, rig_.snapshot(), judging.judge(), obs_);
  script::BotAction action;
  try {
    action = bot_.act(obs_);
  } catch (const script::ScriptError& e) {
    judging.fail(std::string("bot error: ") + e.what());
    return false;
  }
  if (std::string why = bot_.giveUpReason(); !why.empty()) {
    judging.fail(why);
    return false;
  }
  const Vec3 position = physics::vec3Of(action.position);
  if (botDevice_ != nullptr) {
    if (action.hasVelocity)
      botDevice_->setPose(position, physics::vec3Of(action.velocity));
    else
      botDevice_->setPose(position);
  } else {
    if (action.hasVelocity)
      handoff_->publish(time, position, physics::vec3Of(action.velocity));
    else
      handoff_->publish(time, position);
  }
  if (guide_) rig_.loop().publishGuide(guideSampleOf(*guide_, obs_));
  return true;
}

// Headless: each script's time in Lua, and the autopilot's planning, are
// bounded by multiples of the simulated time (TrialTiming.h).
void BotTrial::runStepping() {
  begin(script::TrialTiming{});
  TrialJudge& judging = rig_.judging();
  haptics::ServoLoop& loop = rig_.loop();
  const auto maxTicks =
      static_cast<std::uint64_t>(std::ceil(level_.def.task.timeLimit * settings_.maxTimeFactor / rig_.loopDef().period)) + 1;
  while (!judging.finished() && loop.ticks() < maxTicks) {
    if (!answer(loop.time(), loop.state())) break;
    rig_.step();
  }
  if (!judging.finished()) judging.fail("the trial did not end within its time limit");
}

// Every call a tick makes (the bot's act, the level's on_update) has the
// bot's period as its CPU deadline.
void BotTrial::runThreaded() {
  begin(script::TrialTiming{.realtime = true, .tickSeconds = 1.0 / kRealtimeBotRate});
  if (rig_.judging().finished() || !answer(0.0, rig_.initial())) return;  // a pose before the first tick
  rig_.startLoop();
  paceBot();
  rig_.stopLoop();
}

// Every bot period: judge what the loop ran, then answer its latest tick.
void BotTrial::paceBot() {
  TrialJudge& judging = rig_.judging();
  haptics::SteadyServoClock clock;
  const auto botPeriod = static_cast<std::int64_t>(std::llround(1e9 / kRealtimeBotRate));
  std::int64_t deadline = clock.now() + botPeriod;
  // A loop that stops ticking (it should not) must not hang the command.
  const double wallLimit = level_.def.task.timeLimit * settings_.maxTimeFactor + 10.0;
  double botTime = 0.0;  // simulation time of the last observation the bot answered
  while (!judging.finished()) {
    rig_.drain();
    if (judging.finished()) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count() > wallLimit) {
      judging.fail("the servo loop stalled");
      break;
    }
    const haptics::ServoSnapshot& latest = rig_.snapshot();
    if (rig_.takeLatest() && latest.time > botTime) {
      if (!answer(latest.time, physics::forceStateOf(latest.state))) break;
      botTime = latest.time;
    }
    clock.waitUntil(deadline);
    deadline += botPeriod;
  }
}

}  // namespace hemiroll::game
