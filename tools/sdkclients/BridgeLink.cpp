#include "tools/sdkclients/BridgeLink.h"

#include <cmath>

namespace hemiroll::sdkclients {

namespace udp = haptics::udp;

std::string BridgeLink::open() {
  if (const auto why = def_.axes.problem()) return *why;
  if (!(def_.maxForce > 0.0) || !std::isfinite(def_.maxForce)) return "the device's force limit must be above 0 N";
  if (!haptics::parseIpv4(def_.host, bridge_.address))
    return "the bridge's host '" + def_.host + "' is not an IPv4 address like 127.0.0.1";
  bridge_.port = def_.port;
  haptics::UdpEndpoint local;
  local.address = haptics::isLoopback(bridge_.address) ? 0x7F000001u : 0u;
  return socket_.bind(local);
}

void BridgeLink::take(const udp::ForceMessage& m, std::int64_t nowNs) {
  ++counters_.forcesReceived;
  if (!sequence_.take(m.sequence, counters_.forcesLost)) {
    ++counters_.forcesOutOfOrder;
    return;
  }
  counters_.lastStatus = m.status;
  counters_.lastSafetyFault = m.status == udp::BridgeStatus::SafetyStop ? m.safetyFault : 0;
  if (m.status == udp::BridgeStatus::Closing) counters_.bridgeClosing = true;
  holding_ = m.status == udp::BridgeStatus::Ok;
  if (holding_) {
    counters_.anyOkForce = true;
    heldForce_ = {m.force[0], m.force[1], m.force[2]};
    heldSinceNs_ = nowNs;
  }
}

Vec3 BridgeLink::exchange(const DeviceSample& sample, std::int64_t nowNs) {
  udp::StateMessage state;
  state.sequence = nextSequence_++;
  state.timestampNs = static_cast<std::uint64_t>(nowNs);
  const Vec3 p = def_.axes.positionToBridge(sample.position), v = def_.axes.velocityToBridge(sample.velocity);
  state.position = {p[0], p[1], p[2]};
  state.velocity = {v[0], v[1], v[2]};
  state.buttons = sample.buttons;
  state.deviceStatus = sample.deviceFault ? 1 : 0;
  std::uint8_t buffer[udp::kMaxDatagram];
  const std::size_t length = udp::encodeState(state, buffer);
  if (socket_.send(buffer, length, bridge_)) ++counters_.statesSent;
  else ++counters_.sendsRefused;

  for (;;) {
    haptics::UdpEndpoint from;
    const long got = socket_.receive(buffer, sizeof buffer, from, 0);
    if (got <= 0) break;  // nothing waiting (0), or the socket failed (-1)
    udp::ForceMessage force;
    if (from.address != bridge_.address || from.port != bridge_.port ||
        udp::decodeForce(buffer, static_cast<std::size_t>(got), force) != udp::DecodeError::None) {
      ++counters_.forcesMalformed;
      continue;
    }
    take(force, nowNs);
  }

  if (!holding_ || nowNs - heldSinceNs_ > def_.forceHoldNs || sample.deviceFault) {
    ++counters_.ticksWithoutForce;
    return Vec3{};
  }
  Vec3 f = heldForce_;
  const double size = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  if (size > def_.maxForce) {
    ++counters_.forcesClamped;
    for (double& c : f) c *= def_.maxForce / size;
  }
  return def_.axes.forceToDevice(f);
}

}  // namespace hemiroll::sdkclients
