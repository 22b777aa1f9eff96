#pragma once
// A stand-in for hemiroll's UDP bridge in the SDK clients' tests: it answers
// every state with one force (in the bridge's frame) and a status, and keeps
// the last state it got. The real bridge against the reference client is
// tests/haptics/devices/UdpBridgeEndToEndTest.

#include <atomic>
#include <mutex>
#include <thread>

#include "engine/haptics/UdpProtocol.h"
#include "engine/haptics/UdpSocket.h"

namespace hemiroll::sdkclients::test {

class FakeBridge {
 public:
  explicit FakeBridge(std::array<double, 3> force, haptics::udp::BridgeStatus status = haptics::udp::BridgeStatus::Ok)
      : force_(force), status_(status) {
    haptics::UdpEndpoint local;
    local.address = 0x7F000001u;
    socket_.bind(local);
    thread_ = std::thread([this] { serve(); });
  }
  ~FakeBridge() {
    running_ = false;
    thread_.join();
  }
  std::uint16_t port() const { return socket_.localPort(); }
  haptics::udp::StateMessage lastState() {
    std::lock_guard lock(mutex_);
    return last_;
  }
  std::uint64_t statesReceived() const { return states_.load(); }
  // A silent bridge still reads states but answers none (a stalled hemiroll).
  void setAnswering(bool on) { answering_ = on; }

 private:
  void serve() {
    std::uint8_t buffer[haptics::udp::kMaxDatagram];
    std::uint32_t sequence = 0;
    while (running_) {
      haptics::UdpEndpoint from;
      const long got = socket_.receive(buffer, sizeof buffer, from, 1'000'000);
      haptics::udp::StateMessage state;
      if (got <= 0 || haptics::udp::decodeState(buffer, static_cast<std::size_t>(got), state) !=
                          haptics::udp::DecodeError::None)
        continue;
      {
        std::lock_guard lock(mutex_);
        last_ = state;
      }
      ++states_;
      if (!answering_) continue;
      haptics::udp::ForceMessage f;
      f.sequence = ++sequence;
      f.answers = state.sequence;
      f.echoTimestampNs = state.timestampNs;
      f.force = force_;
      f.status = status_;
      socket_.send(buffer, haptics::udp::encodeForce(f, buffer), from);
    }
  }

  std::array<double, 3> force_;
  haptics::udp::BridgeStatus status_;
  haptics::UdpSocket socket_;
  std::atomic<bool> running_{true}, answering_{true};
  std::atomic<std::uint64_t> states_{0};
  std::mutex mutex_;
  haptics::udp::StateMessage last_;
  std::thread thread_;
};

}  // namespace hemiroll::sdkclients::test
