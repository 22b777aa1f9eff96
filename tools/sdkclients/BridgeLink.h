#pragma once
// One device tick's conversation with hemiroll's UDP bridge, for a client
// whose device SDK calls it from its own servo loop: the device's sample out
// as a state datagram, every force datagram that has arrived read without
// waiting, and the force to apply now back in the device's frame. What a
// client must never do is also here, once: apply a force the bridge did not
// mark ok, hold one longer than the bridge's watchdog, or exceed the
// device's continuous force. No allocation and no blocking after open(), so
// it may run inside an SDK's servo callback.

#include <cstdint>
#include <string>

#include "engine/haptics/UdpProtocol.h"
#include "engine/haptics/UdpSocket.h"
#include "tools/sdkclients/AxisMap.h"

namespace hemiroll::sdkclients {

struct BridgeLinkDef {
  std::string host = "127.0.0.1";
  std::uint16_t port = 47110;
  AxisMap axes;
  double maxForce = 3.0;             // the device's continuous force [N]; larger forces are scaled down to it
  std::int64_t forceHoldNs = 10'000'000;  // a force older than this is dropped (the bridge's own watchdog time)
};

// What the device reads in one tick, in its own frame and units.
struct DeviceSample {
  Vec3 position{};
  Vec3 velocity{};
  std::uint32_t buttons = 0;
  bool deviceFault = false;  // the SDK reported an error this tick
};

struct LinkCounters {
  std::uint64_t statesSent = 0, sendsRefused = 0;
  std::uint64_t forcesReceived = 0, forcesMalformed = 0, forcesOutOfOrder = 0, forcesLost = 0;
  std::uint64_t forcesClamped = 0;   // forces scaled down to maxForce
  std::uint64_t ticksWithoutForce = 0;  // ticks that applied zero because no fresh ok force was held
  haptics::udp::BridgeStatus lastStatus = haptics::udp::BridgeStatus::Ok;
  std::uint8_t lastSafetyFault = 0;
  bool anyOkForce = false;  // the bridge has answered with an ok force at least once
  bool bridgeClosing = false;
};

class BridgeLink {
 public:
  explicit BridgeLink(BridgeLinkDef def) : def_(std::move(def)) {}

  // Binds a socket and names the bridge; "" or the reason it cannot.
  std::string open();

  // Sends the sample as a state stamped nowNs, takes every force waiting,
  // and returns the force to apply now [N, device frame].
  Vec3 exchange(const DeviceSample& sample, std::int64_t nowNs);

  const LinkCounters& counters() const { return counters_; }

 private:
  void take(const haptics::udp::ForceMessage& m, std::int64_t nowNs);

  BridgeLinkDef def_;
  haptics::UdpSocket socket_;
  haptics::UdpEndpoint bridge_;
  LinkCounters counters_;
  std::uint32_t nextSequence_ = 1;
  haptics::udp::SequenceBook sequence_;  // the bridge's force datagrams
  Vec3 heldForce_{};            // bridge frame [N], the last ok force
  std::int64_t heldSinceNs_ = 0;
  bool holding_ = false;
};

}  // namespace hemiroll::sdkclients
