#pragma once
// The 1 kHz servo loop: one tick is
//   read device pose -> map to the scene -> hold the proxy -> physics step
//   (Stepper, RK4, h = period) -> domain events -> coupling forces
//   (+ guidance towards the latest published plan, Guidance.h) -> safety
//   -> force to the device -> publish a snapshot.
// The tick allocates nothing, takes no lock, does no I/O and calls no Lua;
// other threads talk to it only through the command ring (one producer) and
// the snapshot triple buffer (one consumer).
//
// Three ways to run the same tick():
//   start()/stop()   a dedicated std::thread on the real monotonic clock,
//                    SCHED_FIFO when permitted (a note in realtime() if not);
//   runPaced(clock)  the same pacing on the calling thread with any clock
//                    (tests inject a fake one);
//   runHeadless(n)   n ticks back to back with no clock at all: as fast as
//                    the CPU allows and bit-for-bit deterministic.
//
// Pacing: deadlines are absolute, d_{k+1} = d_k + period, so sleeping does
// not accumulate drift. The clock sleeps until shortly before the deadline
// and spins the rest (ServoClock.h).
//
// Catch-up policy, when a wake-up comes late by L >= 0:
//   due = 1 + floor(L / period) deadlines have passed;
//   - due <= maxCatchUpTicks: all due ticks run back to back, the deadline
//     grid is kept (d += due * period) and nothing is lost;
//   - due >  maxCatchUpTicks: only maxCatchUpTicks ticks run, the other
//     due - maxCatchUpTicks are skipped and counted as missed ticks, and the
//     grid is re-anchored at now + period. Simulation time advances only by
//     the ticks that run (the world slows down for a moment; it never jumps
//     and never tries to catch up a backlog - no spiral of death).
// A device without force output (the mouse) runs with a larger
// maxCatchUpTicks (game/trial/TrialRig: kForcelessCatchUpTicks): a stall the
// watchdog would stop a force device for is caught up in full up to that
// many ticks and slows the clock beyond; stalls() counts such wake-ups
// (later than safety.maxTickLateness), what a summary says about them.
// Timing statistics: the lateness of every tick run (its start after its
// deadline) and the period between wake-ups, in TimingHistograms; missed
// ticks and ticks run as counters. All readable from any thread at any time.

#include <array>
#include <atomic>
#include <cstdint>
#include <thread>

#include "engine/haptics/ForceSafety.h"
#include "engine/haptics/Guidance.h"
#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/RealtimeThread.h"
#include "engine/haptics/RecordRow.h"
#include "engine/haptics/ServoClock.h"
#include "engine/haptics/ServoCommand.h"
#include "engine/haptics/ServoSnapshot.h"
#include "engine/haptics/SpscRing.h"
#include "engine/haptics/TimingHistogram.h"
#include "engine/haptics/TripleBuffer.h"
#include "engine/haptics/WorkspaceMapping.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/Integrator.h"
#include "engine/physics/Stepper.h"

namespace hemiroll::haptics {

struct ServoLoopDef {
  double period = 0.001;                 // tick period and physics step h [s]
  int maxCatchUpTicks = 3;               // ticks one late wake-up may run (see the policy above)
  std::int64_t spinMarginNs = 50'000;    // sleep until this long before a deadline, then spin [ns]
  bool requestRealtime = true;           // ask for SCHED_FIFO
  int realtimePriority = 80;             // SCHED_FIFO priority, 1..99
  physics::HemisphereParams params;
  physics::DomainLimits limits;
  physics::CouplingDef coupling;         // must pass validateCoupling and the device's maxStiffness
  WorkspaceMapping mapping;
  SafetyDef safety;
  GuidanceDef guidance;                  // none by default; the plan comes through publishGuide()
  std::array<double, 12> initialState{};  // 12-state (physics/StateLayout.h)
  double startTime = 0.0;                // [s]
  // Recording (see above); null rings record nothing. The rings must outlive
  // the loop's ticks; their single consumer is the recorder's thread.
  RecordRing* recordRing = nullptr;
  int recordEvery = 10;                  // ticks per recorded row: 10 = 100 Hz at 1 kHz, 1 = every tick
  InputRing* inputRing = nullptr;        // every tick's device reading (replays)
  CommandRing* commandRing = nullptr;    // every command applied (replays)
  // start()'s thread paces by this clock; null = SteadyServoClock. Tests
  // give one that stalls on request, as a starved thread would.
  ServoClock* clock = nullptr;
};

// The loop's timing in one struct, for a status line or a recording's
// metadata. Quantiles are upper edges of 1 us bins [s].
struct LoopTimingSummary {
  double latenessP50 = 0.0, latenessP99 = 0.0, latenessP999 = 0.0, latenessMax = 0.0;  // [s]
  double periodP50 = 0.0, periodMax = 0.0;                                             // [s] between wake-ups
  std::uint64_t ticks = 0, missedTicks = 0, wakeups = 0;
  std::uint64_t stalls = 0;  // wake-ups later than the safety's maxTickLateness
};

class ServoLoop {
 public:
  static constexpr std::size_t kCommandCapacity = 64;

  // The device is opened and closed by the caller; the loop only reads it and
  // sends forces. Throws std::invalid_argument for an invalid definition.
  ServoLoop(const ServoLoopDef& def, HapticDevice& device);
  ~ServoLoop();
  // Empty when `device` can render the coupling stably, else why not (what
  // the constructor and post() refuse): for checking a plan of trials
  // before the first one runs.
  static std::string couplingProblem(const physics::CouplingDef& coupling, const DeviceSpec& device);
  ServoLoop(const ServoLoop&) = delete;
  ServoLoop& operator=(const ServoLoop&) = delete;

  // Dedicated thread on the real clock. stop() joins it and sends a zero force.
  void start();
  void stop();
  bool running() const { return thread_.joinable(); }

  // Same pacing on the calling thread, for at most maxWakeups wake-ups (or
  // until stop() is requested from another thread).
  void runPaced(ServoClock& clock, long maxWakeups);
  // n ticks with no clock (lateness 0).
  void runHeadless(long ticks);
  // One tick; latenessNs only goes into the snapshot.
  void tick(std::int64_t latenessNs = 0);

  // One producer thread. False when the ring is full or the command is
  // invalid (a coupling that fails validateCoupling or exceeds the device's
  // maxStiffness; checked here, outside the tick, because the check
  // allocates its message).
  bool post(const ServoCommand& command);
  // The planner's latest wish for the proxy, for guidance (one producer
  // thread; lock free, latest wins). Ignored without def.guidance.
  void publishGuide(const GuideSample& sample) { guides_.write(sample); }
  // One consumer thread. False until the first tick has published.
  bool latest(ServoSnapshot& out) { return snapshots_.read(out); }
  // The same snapshots for a second consumer thread (a planner beside the
  // renderer: the autopilot watching or hinting in the window).
  // The tick writes this channel only once a planner has asked (a plain
  // trial has none, and a snapshot is a few hundred bytes a tick).
  bool latestForPlanner(ServoSnapshot& out) {
    plannerReads_.store(true, std::memory_order_relaxed);
    return plannerSnapshots_.read(out);
  }

  const TimingHistogram& lateness() const { return lateness_; }
  const TimingHistogram& wakePeriod() const { return period_; }
  std::uint64_t ticks() const { return ticks_.load(std::memory_order_relaxed); }
  std::uint64_t missedTicks() const { return missed_.load(std::memory_order_relaxed); }
  std::uint64_t wakeups() const { return wakeups_.load(std::memory_order_relaxed); }
  // Wake-ups later than safety.maxTickLateness: a stop on a device that
  // renders force, ridden out (caught up, or the clock slowed) on one that does not.
  std::uint64_t stalls() const { return stalls_.load(std::memory_order_relaxed); }
  // Rows, and inputs or commands, lost to a full recording ring since construction.
  std::uint64_t recordDropped() const { return recordDropped_.load(std::memory_order_relaxed); }
  std::uint64_t inputDropped() const { return inputDropped_.load(std::memory_order_relaxed); }
  RealtimeResult realtime() const;
  LoopTimingSummary timingSummary() const;

  // Direct views for the loop's own thread (headless runs and tests).
  const physics::ForceDrivenState& state() const { return stepper_.state(); }
  double time() const { return stepper_.time(); }
  const ForceSafety& safety() const { return safety_; }

 private:
  void drainCommands();
  void apply(const ServoCommand& c);
  void publish(const physics::CouplingForces& forces, double distance, double injected, std::int64_t latenessNs);
  Vec3 guidanceNow();
  void logInput(const DeviceReading& reading, std::int64_t latenessNs);

  ServoLoopDef def_;
  HapticDevice& device_;
  physics::ForceDrivenSystem system_;
  physics::RungeKutta4<12> integrator_;
  physics::Stepper<12> stepper_;
  ForceSafety safety_;
  physics::CouplingDef coupling_;
  physics::ProxyPose proxy_;
  bool paused_ = false;
  // Energy watchdog: model energy at engagement and the hand's work since.
  double energyAtEngage_ = 0.0;
  double handWork_ = 0.0;
  Vec3 lastHandForce_ = Vec3::Zero();
  Vec3 lastRendered_ = Vec3::Zero();
  Vec3 lastGuidance_ = Vec3::Zero();  // scene [N], before safety
  GuideSample guide_;                 // the latest plan this thread has taken
  bool lastClamped_ = false;

  SpscRing<ServoCommand, kCommandCapacity> commands_;
  TripleBuffer<ServoSnapshot> snapshots_;
  TripleBuffer<ServoSnapshot> plannerSnapshots_;
  std::atomic<bool> plannerReads_{false};
  TripleBuffer<GuideSample> guides_;
  TimingHistogram lateness_, period_;
  std::atomic<std::uint64_t> ticks_{0}, missed_{0}, wakeups_{0}, stalls_{0};
  std::atomic<std::uint64_t> recordDropped_{0}, inputDropped_{0};
  double maxLateness_ = 0.0;
  std::atomic<bool> stopRequested_{false};
  std::atomic<int> realtimeStatus_{static_cast<int>(RealtimeStatus::NotRequested)};
  std::atomic<const char*> realtimeNote_{"real-time scheduling not requested"};
  std::thread thread_;
};

}  // namespace hemiroll::haptics
