#pragma once
// A trial played at a real haptic device behind the UDP bridge, without a
// window: `hemiroll run --realtime --device udp` and `hemiroll session
// --device udp` (a participant in a lab at a Touch, an omega, a Falcon).
// Built on the TrialRig the window's PlaySession and the bots use, with its
// threaded driver, so the three cannot drift apart:
//   servo thread:   the bridge's latest state -> coupling -> physics ->
//                   safety (the device profile's limits) -> force to the client;
//   calling thread: every kDeviceDrainPeriod the rig judges and taps every
//                   tick the loop ran (none skipped).
// The clock starts with the device's first state (waitForClient); the
// proxy engages when the handle reaches the mass point (the loop's rule).
// A safety stop ends the trial (nobody is at a screen to clear it), and its
// reason is a sentence a lab technician acts on (DeviceStopWords), with the
// bridge's packet counts beside it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "engine/haptics/ServoClock.h"
#include "engine/haptics/devices/UdpBridgeDevice.h"
#include "engine/record/TrialMeta.h"
#include "engine/script/LevelLoader.h"
#include "game/trial/DeviceStopWords.h"
#include "game/trial/TrialRig.h"

namespace hemiroll::game {

inline constexpr double kDeviceDrainPeriod = 0.002;  // [s] between the judge's drains

struct DeviceTrialDef {
  haptics::UdpBridgeDef bridge;               // its spec: the device profile's (deviceSpecOf)
  std::optional<haptics::SafetyDef> safety;   // the profile's limits (safetyOf); none: the loop's defaults
  std::optional<physics::CouplingDef> coupling;  // none: the level's
  double clientTimeout = 30.0;   // [s] for the device's first state
  bool requestRealtime = true;   // SCHED_FIFO for the servo thread when permitted
  haptics::ServoClock* clock = nullptr;  // the servo thread's clock; null = the real one
  // [s] after a stop, silence this long tells a client that has gone from
  // one that paused past the watchdog.
  double goneAfter = 0.25;
};

class DeviceTrial {
 public:
  // Opens the bridge. Throws std::runtime_error "UDP bridge: ..." when it
  // cannot, std::invalid_argument for a level the loop refuses.
  DeviceTrial(script::LoadedLevel& level, const DeviceTrialDef& def);
  ~DeviceTrial();
  DeviceTrial(const DeviceTrial&) = delete;
  DeviceTrial& operator=(const DeviceTrial&) = delete;

  // Its loop definition and record tap, before run().
  TrialRig& rig() { return rig_; }

  // Waits for the client, then plays to the end, once.
  TrialResult run();

  haptics::UdpBridgeCounters counters() const { return bridge_->counters(); }
  // The bridge's port (the one asked for, or the free one given for port 0).
  std::uint16_t port() const { return bridge_->port(); }
  // The safety stop that ended the trial (None: it ended by its task).
  haptics::SafetyFault stop() const { return stop_; }
  // The stop in words; "" when there was none.
  const std::string& stopWords() const { return stopWords_; }
  // False when no client sent a state within the timeout: the trial was
  // never played (a session does not count it: the next sitting plays it).
  bool clientCame() const { return clientCame_; }
  haptics::LoopTimingSummary timing() const { return rig_.loop().timingSummary(); }

 private:
  void play(double wallLimit);
  void noteStop();

  script::LoadedLevel& level_;
  DeviceTrialDef def_;
  haptics::UdpBridgeDevice* bridge_ = nullptr;  // the rig's device
  TrialRig rig_;
  haptics::SafetyFault stop_ = haptics::SafetyFault::None;
  BridgeFacts facts_;
  std::string stopWords_;
  bool clientCame_ = false;
};

// results.csv's device columns, the same names for every trial so that a
// bot's rows and a device's share a header: device ("udp" for a trial here,
// else `device`: "bot", or the window's "mouse", ...), stop (the words, ""
// without a stop), packets_received, packets_lost, packets_out_of_order,
// packets_late, packets_malformed ("" without a DeviceTrial).
record::Fields deviceResultFields(const DeviceTrial* trial, const std::string& device = "bot");
// The same columns for any trial: its device's name, its stop in words ("":
// none), and the bridge's counts (null: not behind the bridge, left empty).
record::Fields deviceResultFields(const std::string& device, const std::string& stop,
                                  const haptics::UdpBridgeCounters* counters);
// The sidecar's outcome.device for a trial at a device: the stop and the counts.
record::Fields deviceOutcomeFields(const DeviceTrial& trial);

}  // namespace hemiroll::game
