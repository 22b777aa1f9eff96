#include "engine/haptics/UdpProtocol.h"

#include <bit>
#include <cmath>

namespace hemiroll::haptics::udp {

namespace {

// Little-endian writers and readers, one byte at a time.
void put8(std::uint8_t*& p, std::uint8_t v) { *p++ = v; }
void put16(std::uint8_t*& p, std::uint16_t v) {
  for (int i = 0; i < 2; ++i) *p++ = static_cast<std::uint8_t>(v >> (8 * i));
}
void put32(std::uint8_t*& p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) *p++ = static_cast<std::uint8_t>(v >> (8 * i));
}
void put64(std::uint8_t*& p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) *p++ = static_cast<std::uint8_t>(v >> (8 * i));
}
// IEEE 754 binary64, its bit pattern sent as a little-endian u64.
void putF64(std::uint8_t*& p, double v) { put64(p, std::bit_cast<std::uint64_t>(v)); }
void put3(std::uint8_t*& p, const std::array<double, 3>& v) {
  for (double x : v) putF64(p, x);
}

std::uint8_t get8(const std::uint8_t*& p) { return *p++; }
std::uint16_t get16(const std::uint8_t*& p) {
  std::uint16_t v = 0;
  for (int i = 0; i < 2; ++i) v = static_cast<std::uint16_t>(v | (std::uint16_t{*p++} << (8 * i)));
  return v;
}
std::uint32_t get32(const std::uint8_t*& p) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= std::uint32_t{*p++} << (8 * i);
  return v;
}
std::uint64_t get64(const std::uint8_t*& p) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= std::uint64_t{*p++} << (8 * i);
  return v;
}
double getF64(const std::uint8_t*& p) { return std::bit_cast<double>(get64(p)); }
std::array<double, 3> get3(const std::uint8_t*& p) {
  std::array<double, 3> v{};
  for (double& x : v) x = getF64(p);
  return v;
}
bool finite3(const std::array<double, 3>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void putHeader(std::uint8_t*& p, MessageType type, std::size_t size, std::uint32_t sequence) {
  put32(p, kMagic);
  put8(p, kVersion);
  put8(p, static_cast<std::uint8_t>(type));
  put16(p, static_cast<std::uint16_t>(size));
  put32(p, sequence);
}

// Checks the header against the expected type and size; leaves p after it.
DecodeError checkHeader(const std::uint8_t*& p, std::size_t length, MessageType type, std::size_t size,
                        std::uint32_t& sequence) {
  if (length < kHeaderSize) return DecodeError::TooShort;
  if (get32(p) != kMagic) return DecodeError::BadMagic;
  if (get8(p) != kVersion) return DecodeError::BadVersion;
  if (get8(p) != static_cast<std::uint8_t>(type)) return DecodeError::BadType;
  const std::uint16_t declared = get16(p);
  if (declared != length) return DecodeError::SizeMismatch;
  if (declared != size) return DecodeError::BadSize;
  sequence = get32(p);
  return DecodeError::None;
}

}  // namespace

const char* decodeErrorName(DecodeError e) {
  switch (e) {
    case DecodeError::None: return "none";
    case DecodeError::TooShort: return "shorter than a header";
    case DecodeError::BadMagic: return "wrong magic";
    case DecodeError::BadVersion: return "unsupported protocol version";
    case DecodeError::BadType: return "unexpected message type";
    case DecodeError::SizeMismatch: return "size field differs from the datagram length";
    case DecodeError::BadSize: return "wrong size for the message type";
    case DecodeError::NonFinite: return "NaN or Inf in the numbers";
  }
  return "?";
}

std::size_t encodeState(const StateMessage& m, std::uint8_t* out) {
  std::uint8_t* p = out;
  putHeader(p, MessageType::State, kStateSize, m.sequence);
  put64(p, m.timestampNs);
  put3(p, m.position);
  put3(p, m.velocity);
  put32(p, m.buttons);
  put8(p, m.deviceStatus);
  for (int i = 0; i < 3; ++i) put8(p, 0);  // reserved
  return static_cast<std::size_t>(p - out);
}

std::size_t encodeForce(const ForceMessage& m, std::uint8_t* out) {
  std::uint8_t* p = out;
  putHeader(p, MessageType::Force, kForceSize, m.sequence);
  put32(p, m.answers);
  put64(p, m.echoTimestampNs);
  put3(p, m.force);
  put8(p, static_cast<std::uint8_t>(m.status));
  put8(p, m.safetyFault);
  for (int i = 0; i < 2; ++i) put8(p, 0);  // reserved
  return static_cast<std::size_t>(p - out);
}

DecodeError decodeState(const std::uint8_t* data, std::size_t length, StateMessage& out) {
  const std::uint8_t* p = data;
  StateMessage m;
  const DecodeError header = checkHeader(p, length, MessageType::State, kStateSize, m.sequence);
  if (header != DecodeError::None) return header;
  m.timestampNs = get64(p);
  m.position = get3(p);
  m.velocity = get3(p);
  m.buttons = get32(p);
  m.deviceStatus = get8(p);  // the 3 reserved bytes after it are ignored (future flags)
  if (!finite3(m.position) || !finite3(m.velocity)) return DecodeError::NonFinite;
  out = m;
  return DecodeError::None;
}

DecodeError decodeForce(const std::uint8_t* data, std::size_t length, ForceMessage& out) {
  const std::uint8_t* p = data;
  ForceMessage m;
  const DecodeError header = checkHeader(p, length, MessageType::Force, kForceSize, m.sequence);
  if (header != DecodeError::None) return header;
  m.answers = get32(p);
  m.echoTimestampNs = get64(p);
  m.force = get3(p);
  m.status = static_cast<BridgeStatus>(get8(p));
  m.safetyFault = get8(p);
  if (!finite3(m.force)) return DecodeError::NonFinite;
  out = m;
  return DecodeError::None;
}

}  // namespace hemiroll::haptics::udp
