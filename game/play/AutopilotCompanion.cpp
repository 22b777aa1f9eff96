#include "game/play/AutopilotCompanion.h"

#include <chrono>

#include "engine/physics/StateKinematics.h"
#include "engine/script/ScriptError.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

namespace {

AutopilotBotOptions plannerOnItsOwnThread(bool drives) {
  AutopilotBotOptions o;
  o.plannerThread = true;
  o.holdsProxy = drives;  // watching: its own hand holds the proxy; hint and guide: another's
  // Watching, its hand renders no force and the loop rides a late tick out,
  // so the plan is what wins and planning need not yield to other programs
  // (AutopilotDef::plannerNice). Beside a person's device, which may render
  // force (guidance), it yields as before.
  o.plannerNice = drives ? 0 : 19;
  return o;
}

}  // namespace

AutopilotCompanion::AutopilotCompanion(const task::LevelDef& level, haptics::ServoLoop& loop,
                                       const haptics::WorkspaceMapping& mapping, HandoffBotDevice* hand, bool guide,
                                       std::uint64_t seed)
    : loop_(loop),
      hand_(hand),
      guide_(guide),
      observer_(level.params, mapping),
      autopilot_(plannerOnItsOwnThread(hand != nullptr)) {
  driving_.store(hand != nullptr);
  smoother_.reset(level.params.radius);
  try {
    autopilot_.init(botLevelInfo(level), static_cast<std::int64_t>(seed));
  } catch (const script::ScriptError& e) {
    initError_ = e.what();  // e.g. a visual-only level: no plans, and the reason says why
    reason_ = initError_;
    gaveUp_ = true;
  }
}

AutopilotCompanion::~AutopilotCompanion() { stop(); }

void AutopilotCompanion::start() {
  if (thread_.joinable()) return;
  stopRequested_.store(false);
  thread_ = std::thread([this] { run(); });
}

void AutopilotCompanion::stop() {
  stopRequested_.store(true);
  if (thread_.joinable()) thread_.join();
}

void AutopilotCompanion::publishTask(const task::TaskJudge& judge) {
  script::BotObservation task;
  ObservationBuilder::fillTask(judge, task);
  tasks_.write(task);
}

std::string AutopilotCompanion::giveUpReason() const {
  std::lock_guard<std::mutex> lock(reasonMutex_);
  return reason_;
}

void AutopilotCompanion::run() {
  using Clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / kCompanionRate));
  auto next = Clock::now();
  while (!stopRequested_.load(std::memory_order_relaxed)) {
    step();
    next += period;
    const auto now = Clock::now();
    if (next < now) next = now;  // late: no backlog, the latest snapshot is all that matters
    std::this_thread::sleep_until(next);
  }
}

void AutopilotCompanion::publishHint() {
  const double dt = lastHintTime_ < 0.0 ? 0.0 : obs_.time - lastHintTime_;
  lastHintTime_ = obs_.time;
  const human::HintCue cue = smoother_.cue(autopilot_, obs_, dt);
  HintRing ring;
  ring.kind = cue.kind == human::HintKind::Stir ? HintRing::Stir
              : cue.kind == human::HintKind::Settle ? HintRing::Settle
                                                    : HintRing::None;
  ring.centre[0] = cue.centre.x();
  ring.centre[1] = cue.centre.y();
  ring.radius = cue.radius;
  ring.rate = cue.rate;
  ring.point[0] = cue.point.x();
  ring.point[1] = cue.point.y();
  hints_.write(ring);
}

void AutopilotCompanion::step() {
  if (gaveUp_ || !loop_.latestForPlanner(snapshot_) || snapshot_.tick == lastTick_) return;
  lastTick_ = snapshot_.tick;
  // The task's part as the UI last published it (the latest, new or not),
  // then this tick's kinematics over it. No plan before the first frame
  // has published the goal.
  if (!tasks_.read(obs_)) return;
  // Once the player has taken over, the plan only hints or guides: the
  // autopilot's hand no longer holds the proxy (on this thread, as act).
  if (hand_ != nullptr && !driving() && !letGo_) {
    autopilot_.letGoOfProxy();
    letGo_ = true;
  }
  observer_.fillKinematics(snapshot_.time, physics::forceStateOf(snapshot_.state), snapshot_, obs_);
  const haptics::GuideSample plan = guideSampleOf(autopilot_, obs_);
  if (!plan.valid) {
    gaveUp_ = true;
    std::lock_guard<std::mutex> lock(reasonMutex_);
    reason_ = autopilot_.giveUpReason().empty() ? "autopilot: no plan" : autopilot_.giveUpReason();
  } else if (hand_ != nullptr && driving()) {
    hand_->publish(plan.time, physics::vec3Of(plan.position), physics::vec3Of(plan.velocity));
  }
  if (guide_) loop_.publishGuide(plan);
  plans_.write(plan);
  publishHint();
  planCount_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace hemiroll::game
