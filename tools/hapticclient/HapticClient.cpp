#include "tools/hapticclient/HapticClient.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/haptics/ForceSafety.h"
#include "engine/haptics/RealtimeThread.h"
#include "engine/haptics/ServoClock.h"
#include "engine/haptics/devices/SimulatedHandDevice.h"
#include "engine/haptics/UdpProtocol.h"
#include "engine/haptics/UdpSocket.h"
#include "tools/hapticclient/SimulatedDevice.h"

namespace hemiroll::hapticclient {

using haptics::SimulatedHandDevice;
using haptics::UdpEndpoint;
using haptics::Vec3;
namespace udp = haptics::udp;

namespace {

constexpr double kPi = 3.141592653589793;

SimulatedHandDevice::IntentFunction circleIntent(const ClientOptions& o) {
  const Vec3 c(o.centre[0], o.centre[1], o.centre[2]);
  const double r = o.circleRadius, w = 2.0 * kPi * o.circleFrequency;
  return [c, r, w](double t) {
    SimulatedHandDevice::Intent i;
    i.position = c + Vec3(r * std::sin(w * t), r * (1.0 - std::cos(w * t)), 0.0);
    i.velocity = Vec3(r * w * std::cos(w * t), r * w * std::sin(w * t), 0.0);
    return i;
  };
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::floor(q * static_cast<double>(v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// Receives what the bridge sent; keeps the sequence and round-trip books.
class ForceInbox {
 public:
  // Room for ten minutes at 1 kHz up front; longer runs grow the vector
  // (the client is not a servo tick) rather than reserving gigabytes.
  explicit ForceInbox(std::uint64_t expected) { rtts_.reserve(std::min<std::uint64_t>(expected, 600'000)); }

  void take(const udp::ForceMessage& m, std::int64_t now, DeviceModel& hand, StepWatch& steps, ClientSummary& s) {
    ++s.forcesReceived;
    if (!sequence_.take(m.sequence, s.forcesLost)) {
      ++s.forcesOutOfOrder;
      return;
    }
    if (!haveAnswer_ || udp::sequenceAfter(m.answers, lastAnswer_)) {
      if (!haveAnswer_) firstAnswer_ = m.answers;
      ++s.statesAnswered;
      rtts_.push_back(static_cast<double>(now - static_cast<std::int64_t>(m.echoTimestampNs)) * 1e-9);
      haveAnswer_ = true;
      lastAnswer_ = m.answers;
    }
    if (m.status == udp::BridgeStatus::Stale) ++s.staleForces;
    if (m.status == udp::BridgeStatus::SafetyStop) {
      ++s.safetyStops;
      s.lastSafetyFault = m.safetyFault;
    }
    if (m.status == udp::BridgeStatus::Closing) s.bridgeClosed = true;
    const Vec3 f(m.force[0], m.force[1], m.force[2]);
    hand.setForce(f);
    s.maxForce = std::max(s.maxForce, hand.rendered().norm());
    steps.forceReceived(m.answers, f, now);
  }

  void finish(ClientSummary& s) const {
    s.rttMin = rtts_.empty() ? 0.0 : *std::min_element(rtts_.begin(), rtts_.end());
    s.rttMedian = quantile(rtts_, 0.5);
    s.rttP99 = quantile(rtts_, 0.99);
    s.rttMax = rtts_.empty() ? 0.0 : *std::max_element(rtts_.begin(), rtts_.end());
  }

  // Whether `sequence` lies strictly between the first and the last state
  // the bridge answered: the span in which it saw every gap.
  bool withinAnswered(std::uint32_t sequence) const {
    return haveAnswer_ && udp::sequenceAfter(sequence, firstAnswer_) && udp::sequenceAfter(lastAnswer_, sequence);
  }

 private:
  std::vector<double> rtts_;
  udp::SequenceBook sequence_;  // the bridge's force datagrams
  bool haveAnswer_ = false;
  std::uint32_t firstAnswer_ = 0, lastAnswer_ = 0;
};

DeviceModelDef deviceModelOf(const ClientOptions& o) {
  DeviceModelDef d;
  d.hand = o.hand;
  d.handleMass = o.handleMass;
  d.friction = o.friction;
  d.peakForce = o.peakForce;
  d.resolution = o.resolution;
  return d;
}

LinkFaultsDef linkFaultsOf(const ClientOptions& o) { return {o.jitter, o.loss, o.reorder, o.seed}; }

bool within(double t, double from, double length) { return from >= 0.0 && t >= from && t < from + length; }

void finishSteps(const StepWatch& steps, ClientSummary& s) {
  const std::vector<double>& v = steps.latencies();
  s.steps = v.size();
  s.stepMedian = quantile(v, 0.5);
  s.stepP10 = quantile(v, 0.1);
  s.stepP90 = quantile(v, 0.9);
  s.stepMax = v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

// The bridge's address from --host and --port, and the socket bound to any
// free port (on loopback when the bridge is there); "" or the error.
std::string openSocket(const ClientOptions& o, haptics::UdpSocket& socket, UdpEndpoint& bridge) {
  bridge.port = o.port;
  if (!haptics::parseIpv4(o.host, bridge.address))
    return "--host '" + o.host + "' is not an IPv4 address like 127.0.0.1";
  UdpEndpoint local;  // any free port, on loopback when the bridge is there
  local.address = haptics::isLoopback(bridge.address) ? 0x7F000001u : 0u;
  return socket.bind(local);
}

// The k-th state sent (sequence k + 1) at wall time t: the hand's reading,
// moved by the step's half (the --step square wave on x), and the device's
// fault from --fault-at on.
udp::StateMessage stateMessage(const ClientOptions& o, haptics::DeviceReading r, int half, double t, std::int64_t now,
                               std::uint64_t k) {
  r.position.x() += (half % 2 == 0 ? -0.5 : 0.5) * o.step;
  udp::StateMessage m;
  m.sequence = static_cast<std::uint32_t>(k + 1);
  m.timestampNs = static_cast<std::uint64_t>(now);
  m.position = {r.position.x(), r.position.y(), r.position.z()};
  m.velocity = {r.velocity.x(), r.velocity.y(), r.velocity.z()};
  m.deviceStatus = o.faultAt >= 0.0 && t >= o.faultAt ? 1 : 0;
  return m;
}

}  // namespace

ClientSummary runClient(const ClientOptions& o, const std::atomic<bool>& stop) {
  ClientSummary s;
  UdpEndpoint bridge;
  haptics::UdpSocket socket;
  s.error = openSocket(o, socket, bridge);
  if (!s.error.empty()) return s;

  if (o.realtimePriority > 0)
    s.realtime = haptics::requestFifoScheduling(o.realtimePriority).status == haptics::RealtimeStatus::Fifo;
  DeviceModel hand(circleIntent(o), deviceModelOf(o));
  OutgoingLink link(linkFaultsOf(o));
  StepWatch steps;
  haptics::SteadyServoClock clock;
  const auto periodNs = static_cast<std::int64_t>(std::llround(1e9 / o.rate));
  const auto total = static_cast<std::uint64_t>(std::llround(o.duration * o.rate));
  ForceInbox inbox(total);
  std::vector<std::uint32_t> droppedSequences;
  droppedSequences.reserve(std::min<std::uint64_t>(total, 600'000));
  std::uint8_t buffer[udp::kMaxDatagram];
  const std::int64_t start = clock.now();
  std::int64_t deadline = start;
  std::uint64_t k = 0;
  int lastHalf = 0;  // the step's half-period index

  while (!stop.load(std::memory_order_relaxed)) {
    const std::int64_t now = clock.now();
    link.sendDue(now, [&](const OutgoingLink::Datagram& d) { socket.send(d.data(), d.size(), bridge); });
    if (now >= deadline) {
      if (k == total) break;  // the last force had one period to arrive
      const double t = static_cast<double>(now - start) * 1e-9;
      if (o.exitAt >= 0.0 && t >= o.exitAt) {
        s.exited = true;
        break;
      }
      // The hand lives on wall time, as a real one does: a client that was
      // held up finds its hand where the intent has gone meanwhile.
      const int half = o.step > 0.0 ? static_cast<int>(std::floor(2.0 * t / o.stepPeriod)) : 0;
      const udp::StateMessage m = stateMessage(o, hand.read(t), half, t, now, k);
      if (!within(t, o.pauseAt, o.pauseFor)) {
        OutgoingLink::Datagram d{};
        udp::encodeState(m, d.data());
        const std::uint64_t droppedBefore = link.lost();
        link.push(d, now);
        if (link.lost() != droppedBefore) droppedSequences.push_back(m.sequence);
        link.sendDue(now, [&](const OutgoingLink::Datagram& out) { socket.send(out.data(), out.size(), bridge); });
        if (half != lastHalf && k > 0) steps.stepSent(m.sequence, now);
        lastHalf = half;
        ++s.statesSent;
      }
      ++k;
      // Absolute deadlines; after a long stall, re-anchor instead of bursting.
      if (now - deadline > periodNs) {
        ++s.lateSends;
        deadline = now + periodNs;
      } else {
        deadline += periodNs;
      }
      continue;
    }
    UdpEndpoint from;
    const long n = socket.receive(buffer, sizeof buffer, from, std::min(deadline, link.nextRelease()) - now);
    if (n <= 0 || !(from == bridge)) continue;
    udp::ForceMessage f;
    if (udp::decodeForce(buffer, static_cast<std::size_t>(n), f) != udp::DecodeError::None) {
      ++s.forcesMalformed;
      continue;
    }
    inbox.take(f, clock.now(), hand, steps, s);
  }
  inbox.finish(s);
  finishSteps(steps, s);
  s.statesDropped = link.lost();
  s.statesDroppedWhileAnswered = static_cast<std::uint64_t>(
      std::count_if(droppedSequences.begin(), droppedSequences.end(),
                    [&](std::uint32_t sequence) { return inbox.withinAnswered(sequence); }));
  s.statesReordered = link.reordered();
  return s;
}

void printSummary(const ClientSummary& s, std::ostream& out) {
  out << "states_sent " << s.statesSent << "\n"
      << "late_sends " << s.lateSends << "\n"
      << "forces_received " << s.forcesReceived << "\n"
      << "forces_malformed " << s.forcesMalformed << "\n"
      << "forces_out_of_order " << s.forcesOutOfOrder << "\n"
      << "forces_lost " << s.forcesLost << "\n"
      << "states_answered " << s.statesAnswered << "\n"
      << "stale_forces " << s.staleForces << "\n"
      << "safety_stops " << s.safetyStops << (s.safetyStops > 0 ? std::string(" (last: ") +
             haptics::safetyFaultName(static_cast<haptics::SafetyFault>(s.lastSafetyFault)) + ")" : std::string())
      << "\n"
      << "states_dropped " << s.statesDropped << "\n"
      << "states_reordered " << s.statesReordered << "\n"
      << "exited " << (s.exited ? 1 : 0) << "\n"
      << "steps " << s.steps << "\n"
      << "step_latency_median_us " << s.stepMedian * 1e6 << "\n"
      << "step_latency_p10_us " << s.stepP10 * 1e6 << "\n"
      << "step_latency_p90_us " << s.stepP90 * 1e6 << "\n"
      << "step_latency_max_us " << s.stepMax * 1e6 << "\n"
      << "realtime " << (s.realtime ? 1 : 0) << "\n"
      << "bridge_closed " << (s.bridgeClosed ? 1 : 0) << "\n"
      << "max_force_N " << s.maxForce << "\n"
      << "rtt_min_us " << s.rttMin * 1e6 << "\n"
      << "rtt_median_us " << s.rttMedian * 1e6 << "\n"
      << "rtt_p99_us " << s.rttP99 * 1e6 << "\n"
      << "rtt_max_us " << s.rttMax * 1e6 << "\n";
}

}  // namespace hemiroll::hapticclient
