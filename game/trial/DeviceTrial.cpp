#include "game/trial/DeviceTrial.h"

#include <chrono>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "engine/haptics/devices/DeviceNames.h"
namespace hemiroll::game {

namespace {

TrialRigDef rigDefOf(const DeviceTrialDef& def) {
  TrialRigDef rig;
  rig.device = haptics::kUdpDevice;  // the level's mapping for a device behind the bridge
  rig.coupling = def.coupling;
  rig.safety = def.safety;
  rig.threaded = true;
  rig.requestRealtime = def.requestRealtime;
  rig.clock = def.clock;
  rig.faultsEndTrial = true;  // no operator at a screen to clear it
  return rig;
}

std::string noClient(const haptics::UdpBridgeDef& b, std::uint16_t port, double timeout) {
  std::ostringstream out;
  out << "no device: no state from a client on " << b.bindAddress << ":" << port << " within " << timeout
      << " s; start the device's client (docs/UDP_BRIDGE.md) before the trial";
  return out.str();
}

}  // namespace

DeviceTrial::DeviceTrial(script::LoadedLevel& level, const DeviceTrialDef& def)
    : level_(level),
      def_(def),
      rig_(level, rigDefOf(def), [this](const haptics::ServoLoopDef&) -> std::unique_ptr<haptics::HapticDevice> {
        auto bridge = std::make_unique<haptics::UdpBridgeDevice>(def_.bridge);
        if (!bridge->open()) {
          const char* why = bridge->error();
          throw std::runtime_error(why != nullptr ? why : "UDP bridge: could not open");
        }
        bridge_ = bridge.get();
        return bridge;
      }) {
  facts_.present = true;
  facts_.watchdog = def.bridge.watchdog;
}

DeviceTrial::~DeviceTrial() = default;

TrialResult DeviceTrial::run() {
  const auto start = std::chrono::steady_clock::now();
  TrialJudge& judging = rig_.judging();
  // The level's callbacks run on this thread for each drain's ticks.
  level_.script->setTiming({.realtime = true, .tickSeconds = 10 * kDeviceDrainPeriod});
  judging.start(rig_.initial());  // on_start (and on_fail, should it end the trial)
  clientCame_ = judging.finished() || bridge_->waitForClient(def_.clientTimeout);
  if (!clientCame_) judging.fail(noClient(def_.bridge, bridge_->port(), def_.clientTimeout));
  if (!judging.finished()) {
    rig_.post(haptics::ServoCommandKind::Engage);  // engages when the handle reaches the mass point
    rig_.startLoop();
    play(level_.def.task.timeLimit * 1.01 + 10.0);
    rig_.stopLoop();
    rig_.drain();
    noteStop();
  }
  TrialResult result = rig_.result();
  if (!stopWords_.empty()) result.reason = "safety stop: " + stopWords_;
  result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// Every drain period: judge what the loop ran; note the stop while the
// bridge still knows what it saw.
void DeviceTrial::play(double wallLimit) {
  TrialJudge& judging = rig_.judging();
  haptics::SteadyServoClock clock;
  const auto period = static_cast<std::int64_t>(kDeviceDrainPeriod * 1e9);
  std::int64_t deadline = clock.now() + period;
  const std::int64_t end = clock.now() + static_cast<std::int64_t>(wallLimit * 1e9);
  while (!judging.finished()) {
    rig_.drain();
    if (rig_.takeLatest() && rig_.snapshot().fault != haptics::SafetyFault::None && stop_ == haptics::SafetyFault::None) {
      stop_ = rig_.snapshot().fault;
      // A DeviceError behind the bridge is the client's device reporting a
      // fault, or silence past the watchdog (noteStop tells a pause from a
      // client that has gone).
      facts_.deviceStatus = bridge_->lastDeviceFault();
      facts_.stale = facts_.deviceStatus == 0;
    }
    if (judging.finished()) break;
    if (clock.now() > end) {
      judging.fail("the servo loop stalled");
      break;
    }
    clock.waitUntil(deadline);
    deadline += period;
  }
}

// After the loop: a stop the bridge saw as silence is a client that has
// gone when the silence outlasts goneAfter.
void DeviceTrial::noteStop() {
  if (stop_ == haptics::SafetyFault::None) return;
  // Silence is seen by two watchdogs: the bridge's counts wall time, the
  // loop's stale-data one counts ticks, which run ahead of the wall clock
  // while the loop catches up after a stall. Whichever saw it first, the
  // bridge tells a pause from a client that has gone.
  const bool silence = (stop_ == haptics::SafetyFault::DeviceError || stop_ == haptics::SafetyFault::StaleDevice) &&
                       facts_.stale;
  if (silence) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(def_.goneAfter);
    while (bridge_->silentFor() < def_.goneAfter && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    facts_.silentFor = bridge_->silentFor();
    facts_.clientGone = facts_.silentFor >= def_.goneAfter;
  }
  stopWords_ = deviceStopWords(stop_, facts_, stopLimitsOf(rig_.loopDef().safety));
}

record::Fields deviceResultFields(const std::string& device, const std::string& stop,
                                  const haptics::UdpBridgeCounters* c) {
  const auto count = [c](std::uint64_t haptics::UdpBridgeCounters::*field) {
    return c ? std::to_string(c->*field) : std::string();
  };
  return {{"device", device},
          {"stop", stop},
          {"packets_received", count(&haptics::UdpBridgeCounters::accepted)},
          {"packets_lost", count(&haptics::UdpBridgeCounters::lost)},
          {"packets_out_of_order", count(&haptics::UdpBridgeCounters::outOfOrder)},
          {"packets_late", count(&haptics::UdpBridgeCounters::late)},
          {"packets_malformed", count(&haptics::UdpBridgeCounters::malformed)}};
}

record::Fields deviceResultFields(const DeviceTrial* trial, const std::string& device) {
  if (trial == nullptr) return deviceResultFields(device, "", nullptr);
  const haptics::UdpBridgeCounters c = trial->counters();
  return deviceResultFields(haptics::kUdpDevice, trial->stopWords(), &c);
}

record::Fields deviceOutcomeFields(const DeviceTrial& trial) {
  record::Fields out = {{"stop", trial.stopWords()},
                        {"stop_fault", haptics::safetyFaultName(trial.stop())},
                        {"packets", packetCountWords(trial.counters())}};
  return out;
}

}  // namespace hemiroll::game
