#pragma once
// What makes the reference client behave like a physical device rather than
// a perfect one (docs/UDP_BRIDGE.md "A simulated device"): the device's own
// limits and feel between the hand and the wire, the network between the
// client and the bridge, and a square-wave step to time the force's answer.
//   DeviceModel    the hand (SimulatedHandDevice) on a handle with mass and
//                  Coulomb friction, motors that clamp at the peak force,
//                  encoders that quantise the position;
//   OutgoingLink   each state delayed (jitter), lost or sent after the next
//                  one (reorder), from a seeded generator;
//   StepWatch      the latency from each step of the reported position to
//                  the first force that answers it.

#include <array>
#include <cstdint>
#include <deque>
#include <random>
#include <vector>

#include "engine/haptics/devices/SimulatedHandDevice.h"
#include "engine/haptics/UdpProtocol.h"

namespace hemiroll::hapticclient {

struct DeviceModelDef {
  haptics::HandModelDef hand;
  double handleMass = 0.0;   // [kg] added to the hand's
  double friction = 0.0;     // [N] Coulomb, opposing the handle's velocity
  double peakForce = 0.0;    // [N] the motors' clamp (0: none)
  double resolution = 0.0;   // [m] one encoder count (0: exact positions)
};

class DeviceModel {
 public:
  DeviceModel(haptics::SimulatedHandDevice::IntentFunction intent, const DeviceModelDef& def);
  // The handle at time t [s]: quantised position, velocity from the
  // quantised positions (what an encoder-based SDK reports).
  haptics::DeviceReading read(double t);
  // The force the bridge asks for; the motors render it clamped.
  void setForce(const haptics::Vec3& force);
  const haptics::Vec3& rendered() const { return rendered_; }

 private:
  DeviceModelDef def_;
  haptics::SimulatedHandDevice hand_;
  haptics::Vec3 rendered_ = haptics::Vec3::Zero();
  haptics::Vec3 lastPosition_ = haptics::Vec3::Zero();
  double lastTime_ = -1.0;
  double readTime_ = 0.0;  // [s] of the latest read
};

struct LinkFaultsDef {
  double jitter = 0.0;   // [s]
  double loss = 0.0;     // probability
  double reorder = 0.0;  // probability
  std::uint64_t seed = 1;
};

class OutgoingLink {
 public:
  using Datagram = std::array<std::uint8_t, haptics::udp::kStateSize>;
  explicit OutgoingLink(const LinkFaultsDef& def);
  // A state to send at `now` [ns]; it is lost, delayed or held back as drawn.
  void push(const Datagram& d, std::int64_t now);
  // The datagrams due at `now`, in the order they go out.
  template <class Send>
  void sendDue(std::int64_t now, Send&& send) {
    while (!queue_.empty() && queue_.front().release <= now) {
      send(queue_.front().bytes);
      queue_.pop_front();
    }
  }
  // When the next datagram is due [ns] (INT64_MAX: none waiting).
  std::int64_t nextRelease() const;
  std::uint64_t lost() const { return lost_; }
  std::uint64_t reordered() const { return reordered_; }

 private:
  struct Pending {
    std::int64_t release;
    Datagram bytes;
  };
  void enqueue(const Datagram& d, std::int64_t release);

  LinkFaultsDef def_;
  std::mt19937_64 random_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  std::deque<Pending> queue_;  // by release time
  bool holding_ = false;
  Datagram held_{};
  std::uint64_t lost_ = 0, reordered_ = 0;
};

class StepWatch {
 public:
  // A force change larger than `threshold` [N] answers a step.
  explicit StepWatch(double threshold = 0.02) : threshold_(threshold) {}
  // The state `sequence`, sent at `now` [ns], is the first after a step.
  void stepSent(std::uint32_t sequence, std::int64_t now);
  // A force that answers `answers`, received at `now`.
  void forceReceived(std::uint32_t answers, const haptics::Vec3& force, std::int64_t now);
  const std::vector<double>& latencies() const { return latencies_; }  // [s]

 private:
  double threshold_;
  bool waiting_ = false;
  std::uint32_t stepSequence_ = 0;
  std::int64_t stepSentNs_ = 0;
  haptics::Vec3 before_ = haptics::Vec3::Zero(), last_ = haptics::Vec3::Zero();
  std::vector<double> latencies_;
};

}  // namespace hemiroll::hapticclient
