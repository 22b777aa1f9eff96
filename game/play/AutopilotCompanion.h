#pragma once
// The autopilot beside a person's trial in the window, on a thread of its
// own (never the servo thread, never the UI thread's frame): every 2 ms it
// takes the servo loop's latest snapshot (ServoLoop::latestForPlanner), the
// task as the judge last saw it (publishTask, from the UI thread once per
// frame), asks the autopilot where it would put the proxy now, and hands
// that plan to whoever needs it:
//   - the autopilot's hand (HandoffBotDevice) while it drives ("watch");
//   - the servo loop as the guide of haptic guidance (Guidance.h);
//   - the UI as a hint (latestPlan; latestHint, the same plan said as a
//     ring to trace or a spot to settle over, HintSmoother), drawn, moving
//     nothing.
// Every crossing is lock free (TripleBuffers); only the give-up reason, a
// string the UI reads now and then, takes a mutex, which the servo thread
// never touches. The autopilot plans heavy rollouts on its own worker
// (AutopilotBotOptions::plannerThread), so this thread keeps its 500 Hz.

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

#include "engine/haptics/Guidance.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/task/LevelDef.h"
#include "engine/task/TaskJudge.h"
#include "game/trial/AutopilotBot.h"
#include "game/trial/HandoffBotDevice.h"
#include "game/trial/HintSmoother.h"
#include "game/trial/ObservationBuilder.h"

namespace hemiroll::game {

inline constexpr double kCompanionRate = 500.0;  // [Hz]

// The hint at a person's bandwidth (HintSmoother), as the UI draws it: a
// ring to trace at a pace, or a spot to settle over. Plain values: it
// crosses threads through a TripleBuffer.
struct HintRing {
  enum Kind : int { None, Stir, Settle } kind = None;
  double centre[2] = {0.0, 0.0};  // Stir: the ring's centre on the floor [m]
  double radius = 0.0;            // Stir [m]
  double rate = 0.0;              // Stir: [rad/s], positive anticlockwise seen from above
  double point[2] = {0.0, 0.0};   // Settle: where the proxy should stand [m]
};

class AutopilotCompanion {
 public:
  // `loop` and `hand` (nullptr: it never drives) must outlive the companion.
  // `guide`: publish the plan to the loop as the guidance's target.
  AutopilotCompanion(const task::LevelDef& level, haptics::ServoLoop& loop, const haptics::WorkspaceMapping& mapping,
                     HandoffBotDevice* hand, bool guide, std::uint64_t seed = 0);
  ~AutopilotCompanion();
  AutopilotCompanion(const AutopilotCompanion&) = delete;
  AutopilotCompanion& operator=(const AutopilotCompanion&) = delete;

  void start();
  void stop();  // joins; idempotent

  // UI thread, once per frame: the task's part of the observation.
  void publishTask(const task::TaskJudge& judge);
  // UI thread: the latest plan (valid false before the first and after a give-up).
  bool latestPlan(haptics::GuideSample& out) { return plans_.read(out); }
  // UI thread: the latest hint at a person's bandwidth (false before the first).
  bool latestHint(HintRing& out) { return hints_.read(out); }
  // Any thread: stop handing poses to the autopilot's hand (the player took over).
  void stopDriving() { driving_.store(false, std::memory_order_release); }
  bool driving() const { return driving_.load(std::memory_order_acquire); }
  // UI thread: why the autopilot gave up ("" while it plans).
  std::string giveUpReason() const;
  // Plans made since start (for a status line and the screen tests).
  std::uint64_t plans() const { return planCount_.load(std::memory_order_relaxed); }
  // Any thread: the planner's decisions applied, and those dropped late or stale.
  autopilot::RealTimePlanCounts decisions() const {
    const autopilot::Autopilot* a = autopilot_.autopilot();
    return a != nullptr ? a->realTimePlans() : autopilot::RealTimePlanCounts{};
  }

 private:
  void run();
  void step();
  void publishHint();

  haptics::ServoLoop& loop_;
  HandoffBotDevice* hand_;
  bool guide_;
  ObservationBuilder observer_;
  bool letGo_ = false;  // companion thread: letGoOfProxy done
  AutopilotBot autopilot_;
  std::string initError_;
  haptics::TripleBuffer<script::BotObservation> tasks_;
  haptics::TripleBuffer<haptics::GuideSample> plans_;
  haptics::TripleBuffer<HintRing> hints_;
  HintSmoother smoother_;  // companion thread
  double lastHintTime_ = -1.0;
  // Companion thread only.
  script::BotObservation obs_;
  haptics::ServoSnapshot snapshot_;
  std::uint64_t lastTick_ = 0;
  bool gaveUp_ = false;

  std::atomic<bool> driving_{true}, stopRequested_{false};
  std::atomic<std::uint64_t> planCount_{0};
  mutable std::mutex reasonMutex_;
  std::string reason_;
  std::thread thread_;
};

}  // namespace hemiroll::game
