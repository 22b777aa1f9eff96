#pragma once
// A real haptic device (PHANToM/Touch, Falcon, Force Dimension, ...) driven by
// a small external program that speaks the UDP bridge protocol
// (UdpProtocol.h, docs/UDP_BRIDGE.md): it sends the device's state at 1 kHz
// and applies the force that comes back.
//
// Threads:
//   - a receiver thread (started by open(), joined by close()) owns every
//     recvfrom: it decodes, validates, counts and drops bad datagrams, and
//     hands the latest good state to the servo thread through a TripleBuffer
//     (lock free, wait free, no allocation);
//   - the servo thread calls read() and sendForce(). sendForce() encodes into
//     a stack buffer and does one non-blocking sendto (MSG_DONTWAIT): it
//     cannot wait, allocates nothing in user space, and answers exactly the
//     state the force was computed from. Sending from the receiver thread
//     instead would need a wake-up (another syscall and a thread switch) and
//     would delay every force by that thread's scheduling.
//
// Watchdog: read() compares the arrival time of the latest good state with
// the monotonic clock. After `watchdog` (10 ms) without one, error() says so
// and the loop's ForceSafety latches a DeviceError: zero force at once, play
// paused with that sentence as the reason. This is the bridge's own clock,
// independent of the loop's tick count, so a stalled servo thread cannot
// hide a silent client. ForceSafety's stale-data watchdog (staleLimit, also
// 10 ms of non-fresh reads) is a second, independent line behind it. Before
// the first good state error() says that no client has spoken yet, so start
// the loop after waitForClient().
//
// Security: binds to 127.0.0.1 by default. Any other address (a device on
// another machine) must be asked for with allowNonLoopback, because anyone
// who can reach the port can steer the proxy. One client at a time: while
// the current client is alive, datagrams from any other sender are dropped.

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include "engine/haptics/HapticDevice.h"
#include "engine/haptics/MonotonicClock.h"
#include "engine/haptics/RealtimeThread.h"
#include "engine/haptics/TripleBuffer.h"
#include "engine/haptics/UdpProtocol.h"
#include "engine/haptics/UdpSocket.h"

namespace hemiroll::haptics {

struct UdpBridgeDef {
  std::string bindAddress = "127.0.0.1";
  std::uint16_t port = 47110;        // 0: any free port (tests; see UdpBridgeDevice::port())
  bool allowNonLoopback = false;     // required for any address outside 127.0.0.0/8
  double watchdog = 0.010;           // [s] without a good state -> error
  // [s] a good state arriving this long after the previous one is counted
  // late (twice a 1 kHz client's period: its scheduler or the network held it).
  double latePacket = 0.002;
  MonotonicClock clock = &monotonicNowNs;
  // SCHED_FIFO priority of the receiver thread, when permitted (0: do not
  // ask). Just below the servo loop's 80: a receiver starved by other work
  // would look like a silent client and trip the watchdog.
  int receiverPriority = 79;
  // The spec of the device behind the bridge: the client knows the hardware,
  // the level sets these to its limits. Defaults suit a Touch-class device.
  DeviceSpec spec{"udp bridge", 3.0, 1000.0, 0.1, true};
};

// Counters, readable from any thread.
struct UdpBridgeCounters {
  std::uint64_t received = 0;     // datagrams of any kind
  std::uint64_t accepted = 0;     // good states handed to the loop
  std::uint64_t malformed = 0;    // failed to decode (magic, version, type, size, NaN)
  std::uint64_t outOfOrder = 0;   // sequence not after the last accepted one (late or duplicate)
  std::uint64_t lost = 0;         // states that never arrived (a gap not filled by a late one within 63 states)
  std::uint64_t late = 0;         // accepted states that arrived more than latePacket after the previous one
  std::uint64_t otherSender = 0;  // from a second sender while the client was alive
  std::uint64_t clientChanges = 0;
  std::uint64_t forcesSent = 0;
  std::uint64_t sendFailures = 0;
};

class UdpBridgeDevice final : public HapticDevice {
 public:
  explicit UdpBridgeDevice(const UdpBridgeDef& def = {});
  ~UdpBridgeDevice() override;

  const DeviceSpec& spec() const override { return def_.spec; }
  bool open() override;
  void close() override;
  DeviceReading read(double t) override;
  void sendForce(const Vec3& force) override;
  // A safety stop is sent to the client as status SafetyStop with the fault.
  void safetyState(std::uint8_t fault) override { safetyFault_ = fault; }
  const char* error() const override;

  std::uint16_t port() const { return socket_.localPort(); }
  // What the scheduler granted the receiver thread (after open()).
  RealtimeResult receiverRealtime() const;
  UdpBridgeCounters counters() const;
  udp::DecodeError lastDecodeError() const { return lastDecodeError_.load(std::memory_order_relaxed); }
  // Seconds since the latest good state arrived (on the bridge's clock);
  // negative before the first. What tells a client that is gone from one
  // that paused past the watchdog.
  double silentFor() const;
  // The device status byte of the latest good state that reported a fault (0: none has).
  std::uint8_t lastDeviceFault() const { return lastDeviceFault_.load(std::memory_order_relaxed); }
  // Outside the loop: waits until a client has sent a good state.
  bool waitForClient(double timeout) const;
  bool ready() const override { return waitForClient(0.0); }

 private:
  // What the receiver hands to the servo thread.
  struct Sample {
    udp::StateMessage state;
    std::int64_t arrivalNs = 0;
    UdpEndpoint client;
    std::uint64_t serial = 0;  // accepted count; a change means a fresh sample
  };
  std::uint8_t safetyFault_ = 0;  // the servo thread's, set before each sendForce
  enum class Health { NotOpen, NoClient, Ok, Stale, DeviceFault };

  void receiveLoop();
  void accept(const udp::StateMessage& m, const UdpEndpoint& from, std::int64_t arrival);

  UdpBridgeDef def_;
  UdpSocket socket_;
  std::string openError_;
  std::thread receiver_;
  std::atomic<bool> stop_{false};
  std::atomic<int> receiverStatus_{static_cast<int>(RealtimeStatus::NotRequested)};
  std::atomic<const char*> receiverNote_{"real-time scheduling not requested"};
  TripleBuffer<Sample> samples_;

  // Receiver thread only.
  UdpEndpoint client_;
  bool haveClient_ = false;
  std::uint32_t lastSequence_ = 0;
  // Bit d: the state d sequence numbers behind lastSequence_ was skipped
  // (counted lost). One arriving late, within 63, was not lost after all:
  // it counts out of order only.
  std::uint64_t skipped_ = 0;
  std::int64_t lastArrival_ = 0;

  // Servo thread only (read/sendForce).
  Sample current_;
  std::uint64_t lastSerial_ = 0;
  std::uint32_t forceSequence_ = 0;
  std::atomic<Health> health_{Health::NotOpen};

  std::atomic<udp::DecodeError> lastDecodeError_{udp::DecodeError::None};
  std::atomic<std::int64_t> lastGoodNs_{0};  // arrival of the latest good state (0: none yet)
  std::atomic<std::uint8_t> lastDeviceFault_{0};
  std::atomic<std::uint64_t> received_{0}, accepted_{0}, malformed_{0}, outOfOrder_{0}, lost_{0}, late_{0}, otherSender_{0},
      clientChanges_{0}, forcesSent_{0}, sendFailures_{0};
};

}  // namespace hemiroll::haptics
