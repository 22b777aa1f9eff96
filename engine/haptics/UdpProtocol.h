#pragma once
// The UDP bridge's wire format (docs/UDP_BRIDGE.md has the byte tables).
// Little-endian, fixed sizes, encoded and decoded byte by byte: no struct is
// ever copied onto the wire, so padding, alignment and the host's byte order
// cannot leak into the protocol.
//
// Every datagram starts with the same 12-byte header:
//   0 u32 magic 0x4C4F5248 ("HROL" on the wire)   4 u8 version (1)
//   5 u8  type (1 state, 2 force)                  6 u16 size (whole datagram)
//   8 u32 sequence (the sender's counter, +1 per datagram, wraps)
// State (client -> bridge, 76 bytes): timestamp [ns], position [m],
// velocity [m/s], buttons, device status. Force (bridge -> client, 52 bytes):
// the state it answers, that state's timestamp echoed, force [N], status.

#include <array>
#include <cstddef>
#include <cstdint>

namespace hemiroll::haptics::udp {

inline constexpr std::uint32_t kMagic = 0x4C4F5248;
inline constexpr std::uint8_t kVersion = 1;
inline constexpr std::size_t kHeaderSize = 12;
inline constexpr std::size_t kStateSize = 76;
inline constexpr std::size_t kForceSize = 52;
// Large enough for any message of this version plus room to detect an
// oversized datagram (which is rejected, never truncated silently).
inline constexpr std::size_t kMaxDatagram = 128;

enum class MessageType : std::uint8_t { State = 1, Force = 2 };

// What the bridge tells the client with every force.
enum class BridgeStatus : std::uint8_t {
  Ok = 0,
  Stale = 1,    // the bridge's watchdog tripped (no state for 10 ms): the force is zero
  Closing = 2,  // the bridge is shutting down: the force is zero and stays so
  DeviceFault = 3,  // the client's device reported a fault (its status byte): the force is zero
  SafetyStop = 4,   // hemiroll's safety layer holds the force at zero; ForceMessage::safetyFault says why
};

struct StateMessage {
  std::uint32_t sequence = 0;
  std::uint64_t timestampNs = 0;  // client's monotonic clock [ns]; echoed back with the force
  std::array<double, 3> position{};  // device frame [m]
  std::array<double, 3> velocity{};  // [m/s]
  std::uint32_t buttons = 0;         // bit i = button i pressed
  std::uint8_t deviceStatus = 0;     // 0 = healthy; any other value = the device reports a fault
};

struct ForceMessage {
  std::uint32_t sequence = 0;
  std::uint32_t answers = 0;         // sequence of the state this force was computed from
  std::uint64_t echoTimestampNs = 0; // that state's timestampNs, for round-trip times
  std::array<double, 3> force{};     // device frame [N]
  BridgeStatus status = BridgeStatus::Ok;
  // With SafetyStop: which watchdog holds the force (haptics::SafetyFault as
  // a number, 1 device error .. 9 position jump; UDP_BRIDGE.md), else 0.
  std::uint8_t safetyFault = 0;
};

enum class DecodeError {
  None,
  TooShort,      // fewer bytes than a header
  BadMagic,
  BadVersion,
  BadType,       // unknown type, or a type the receiver does not accept
  SizeMismatch,  // the header's size differs from the datagram's length
  BadSize,       // the size is not the size of this type
  NonFinite,     // NaN or Inf in a position, velocity or force
};
const char* decodeErrorName(DecodeError e);

// Encoders write exactly kStateSize / kForceSize bytes and return that count.
std::size_t encodeState(const StateMessage& m, std::uint8_t* out);
std::size_t encodeForce(const ForceMessage& m, std::uint8_t* out);

// Decoders check the header, the size and the numbers; out is written only
// when the result is DecodeError::None.
DecodeError decodeState(const std::uint8_t* data, std::size_t length, StateMessage& out);
DecodeError decodeForce(const std::uint8_t* data, std::size_t length, ForceMessage& out);

// True when sequence a comes after b, wrap-around included (serial number
// arithmetic: a is newer when it is less than 2^31 ahead).
inline bool sequenceAfter(std::uint32_t a, std::uint32_t b) {
  return a != b && static_cast<std::uint32_t>(a - b) < 0x80000000u;
}

// A receiver's books on the sender's sequence: a datagram is taken when it
// is after the last one taken (the gap skipped counted into `lost`), else
// it is out of order. The clients' side; the bridge keeps its own, with a
// window that un-counts a skipped state arriving late (UdpBridgeDevice).
struct SequenceBook {
  bool have = false;
  std::uint32_t last = 0;

  bool take(std::uint32_t sequence, std::uint64_t& lost) {
    if (have && !sequenceAfter(sequence, last)) return false;
    if (have) lost += sequence - last - 1;
    have = true;
    last = sequence;
    return true;
  }
};

}  // namespace hemiroll::haptics::udp
