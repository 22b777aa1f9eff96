#include "engine/haptics/devices/UdpBridgeDevice.h"

#include <cmath>
#include <ctime>

#include "engine/haptics/ForceClamp.h"

namespace hemiroll::haptics {

namespace {

// The receiver wakes at least this often to notice close() [ns].
constexpr std::int64_t kReceivePollNs = 20'000'000;

Vec3 toVec3(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

}  // namespace

UdpBridgeDevice::UdpBridgeDevice(const UdpBridgeDef& def) : def_(def) {}

UdpBridgeDevice::~UdpBridgeDevice() { close(); }

bool UdpBridgeDevice::open() {
  close();
  openError_.clear();
  UdpEndpoint local;
  local.port = def_.port;
  if (!(def_.watchdog > 0.0) || !std::isfinite(def_.watchdog) || def_.clock == nullptr) {
    openError_ = "UDP bridge: the watchdog time must be a positive number of seconds";
    return false;
  }
  if (!parseIpv4(def_.bindAddress, local.address)) {
    openError_ = "UDP bridge: bind address '" + def_.bindAddress + "' is not an IPv4 address like 127.0.0.1";
    return false;
  }
  if (!isLoopback(local.address) && !def_.allowNonLoopback) {
    openError_ = "UDP bridge: refusing to bind " + def_.bindAddress +
                 ": only loopback (127.x.x.x) unless explicitly allowed, since anyone who reaches the port "
                 "steers the device";
    return false;
  }
  const std::string problem = socket_.bind(local);
  if (!problem.empty()) {
    openError_ = "UDP bridge: " + problem;
    return false;
  }
  haveClient_ = false;
  lastArrival_ = 0;
  current_ = Sample{};
  lastSerial_ = 0;
  health_.store(Health::NoClient, std::memory_order_relaxed);
  stop_.store(false, std::memory_order_relaxed);
  receiver_ = std::thread([this] { receiveLoop(); });
  return true;
}

void UdpBridgeDevice::close() {
  if (receiver_.joinable()) {
    stop_.store(true, std::memory_order_relaxed);
    receiver_.join();
  }
  if (socket_.isOpen() && current_.serial != 0) {
    // Tell the client the bridge is going: zero force, status Closing.
    udp::ForceMessage m;
    m.sequence = ++forceSequence_;
    m.answers = current_.state.sequence;
    m.echoTimestampNs = current_.state.timestampNs;
    m.status = udp::BridgeStatus::Closing;
    std::uint8_t buffer[udp::kForceSize];
    socket_.send(buffer, udp::encodeForce(m, buffer), current_.client);
  }
  socket_.close();
  health_.store(Health::NotOpen, std::memory_order_relaxed);
}

RealtimeResult UdpBridgeDevice::receiverRealtime() const {
  return {static_cast<RealtimeStatus>(receiverStatus_.load(std::memory_order_acquire)),
          receiverNote_.load(std::memory_order_relaxed)};
}

void UdpBridgeDevice::receiveLoop() {
  if (def_.receiverPriority > 0) {
    const RealtimeResult r = requestFifoScheduling(def_.receiverPriority);
    receiverNote_.store(r.note, std::memory_order_relaxed);
    receiverStatus_.store(static_cast<int>(r.status), std::memory_order_release);
  }
  std::uint8_t buffer[udp::kMaxDatagram];
  while (!stop_.load(std::memory_order_relaxed)) {
    UdpEndpoint from;
    const long n = socket_.receive(buffer, sizeof buffer, from, kReceivePollNs);
    if (n <= 0) continue;
    const std::int64_t arrival = def_.clock();
    received_.fetch_add(1, std::memory_order_relaxed);
    udp::StateMessage m;
    const udp::DecodeError e = udp::decodeState(buffer, static_cast<std::size_t>(n), m);
    if (e != udp::DecodeError::None) {
      lastDecodeError_.store(e, std::memory_order_relaxed);
      malformed_.fetch_add(1, std::memory_order_relaxed);
      continue;
    }
    accept(m, from, arrival);
  }
}

void UdpBridgeDevice::accept(const udp::StateMessage& m, const UdpEndpoint& from, std::int64_t arrival) {
  const auto watchdogNs = static_cast<std::int64_t>(def_.watchdog * 1e9);
  if (haveClient_ && !(from == client_)) {
    // Another sender takes over only once the current client has gone
    // silent (a restarted client gets a new port); meanwhile it is ignored.
    if (arrival - lastArrival_ <= watchdogNs) {
      otherSender_.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    haveClient_ = false;
  }
  if (!haveClient_) {
    client_ = from;
    haveClient_ = true;
    skipped_ = 0;
    clientChanges_.fetch_add(1, std::memory_order_relaxed);
  } else if (!udp::sequenceAfter(m.sequence, lastSequence_)) {
    outOfOrder_.fetch_add(1, std::memory_order_relaxed);
    const std::uint32_t behind = lastSequence_ - m.sequence;
    if (behind >= 1 && behind < 64 && (skipped_ >> behind & 1u) != 0) {
      skipped_ &= ~(std::uint64_t{1} << behind);
      lost_.fetch_sub(1, std::memory_order_relaxed);
    }
    return;
  } else {
    const std::uint32_t gap = m.sequence - lastSequence_;
    skipped_ = gap >= 64 ? 0 : skipped_ << gap;
    for (std::uint32_t d = 1; d < gap && d < 64; ++d) skipped_ |= std::uint64_t{1} << d;
    if (gap > 1) lost_.fetch_add(gap - 1, std::memory_order_relaxed);
  }
  if (lastArrival_ != 0 && arrival - lastArrival_ > static_cast<std::int64_t>(def_.latePacket * 1e9))
    late_.fetch_add(1, std::memory_order_relaxed);
  if (m.deviceStatus != 0) lastDeviceFault_.store(m.deviceStatus, std::memory_order_relaxed);
  lastSequence_ = m.sequence;
  lastArrival_ = arrival;
  lastGoodNs_.store(arrival, std::memory_order_relaxed);
  Sample s;
  s.state = m;
  s.arrivalNs = arrival;
  s.client = from;
  s.serial = accepted_.fetch_add(1, std::memory_order_relaxed) + 1;
  samples_.write(s);
}

DeviceReading UdpBridgeDevice::read(double /*t: the bridge runs on the client's clock*/) {
  Sample s;
  if (samples_.read(s)) current_ = s;
  DeviceReading r;
  r.fresh = current_.serial != lastSerial_;
  lastSerial_ = current_.serial;
  r.position = toVec3(current_.state.position);
  r.velocity = toVec3(current_.state.velocity);
  r.buttons = current_.state.buttons;

  Health h = Health::Ok;
  if (!socket_.isOpen()) {
    h = Health::NotOpen;
  } else if (current_.serial == 0) {
    h = Health::NoClient;
  } else if (def_.clock() - current_.arrivalNs > static_cast<std::int64_t>(def_.watchdog * 1e9)) {
    h = Health::Stale;
  } else if (current_.state.deviceStatus != 0) {
    h = Health::DeviceFault;
  }
  health_.store(h, std::memory_order_relaxed);
  return r;
}

void UdpBridgeDevice::sendForce(const Vec3& force) {
  if (current_.serial == 0 || !socket_.isOpen()) return;
  const Health h = health_.load(std::memory_order_relaxed);
  udp::ForceMessage m;
  m.sequence = ++forceSequence_;
  m.answers = current_.state.sequence;
  m.echoTimestampNs = current_.state.timestampNs;
  // The client hears why its force is zero: silence, its device's own
  // fault, or hemiroll's safety layer (naming the watchdog): never the
  // status of a commanded zero force.
  m.status = h == Health::Stale         ? udp::BridgeStatus::Stale
             : h == Health::DeviceFault ? udp::BridgeStatus::DeviceFault
             : safetyFault_ != 0        ? udp::BridgeStatus::SafetyStop
                                        : udp::BridgeStatus::Ok;
  if (m.status == udp::BridgeStatus::SafetyStop) m.safetyFault = safetyFault_;
  // The safety layer already clamped; the bridge clamps again so that no
  // path through it can exceed the spec, and sends nothing but zero while
  // its watchdog holds.
  if (h == Health::Ok) {
    const Vec3 f = clampForce(force, def_.spec.maxForce).force;
    m.force = {f.x(), f.y(), f.z()};
  }
  std::uint8_t buffer[udp::kForceSize];
  const std::size_t n = udp::encodeForce(m, buffer);
  if (socket_.send(buffer, n, current_.client))
    forcesSent_.fetch_add(1, std::memory_order_relaxed);
  else
    sendFailures_.fetch_add(1, std::memory_order_relaxed);
}

const char* UdpBridgeDevice::error() const {
  switch (health_.load(std::memory_order_relaxed)) {
    case Health::Ok: return nullptr;
    case Health::NotOpen: return openError_.empty() ? "UDP bridge: not open" : openError_.c_str();
    case Health::NoClient: return "UDP bridge: no client has sent a device state yet";
    case Health::Stale: return "UDP bridge watchdog: no device state from the client within the watchdog time (10 ms)";
    case Health::DeviceFault: return "UDP bridge: the client reports a fault of its device";
  }
  return "UDP bridge: unknown state";
}

UdpBridgeCounters UdpBridgeDevice::counters() const {
  UdpBridgeCounters c;
  c.received = received_.load(std::memory_order_relaxed);
  c.accepted = accepted_.load(std::memory_order_relaxed);
  c.malformed = malformed_.load(std::memory_order_relaxed);
  c.outOfOrder = outOfOrder_.load(std::memory_order_relaxed);
  c.lost = lost_.load(std::memory_order_relaxed);
  c.late = late_.load(std::memory_order_relaxed);
  c.otherSender = otherSender_.load(std::memory_order_relaxed);
  c.clientChanges = clientChanges_.load(std::memory_order_relaxed);
  c.forcesSent = forcesSent_.load(std::memory_order_relaxed);
  c.sendFailures = sendFailures_.load(std::memory_order_relaxed);
  return c;
}

double UdpBridgeDevice::silentFor() const {
  const std::int64_t last = lastGoodNs_.load(std::memory_order_relaxed);
  return last == 0 ? -1.0 : static_cast<double>(def_.clock() - last) * 1e-9;
}

bool UdpBridgeDevice::waitForClient(double timeout) const {
  const std::int64_t end = monotonicNowNs() + static_cast<std::int64_t>(timeout * 1e9);
  while (accepted_.load(std::memory_order_relaxed) == 0) {
    if (monotonicNowNs() > end) return false;
    const timespec pause{0, 1'000'000};
    nanosleep(&pause, nullptr);
  }
  return true;
}

}  // namespace hemiroll::haptics
