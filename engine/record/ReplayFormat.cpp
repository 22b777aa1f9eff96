#include "engine/record/ReplayFormat.h"

#include <bit>
#include <cstring>

namespace hemiroll::record {

namespace {

// Byte by byte, least significant first: the same file on every host.
void putU32(unsigned char* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}
void putU64(unsigned char* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}
void putF64(unsigned char* p, double v) { putU64(p, std::bit_cast<std::uint64_t>(v)); }
std::uint32_t getU32(const unsigned char* p) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(p[i]) << (8 * i);
  return v;
}
std::uint64_t getU64(const unsigned char* p) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
  return v;
}
double getF64(const unsigned char* p) { return std::bit_cast<double>(getU64(p)); }

void putText(unsigned char* p, std::size_t size, const std::string& text) {
  std::memcpy(p, text.data(), std::min(text.size(), size - 1));  // always NUL terminated
}
std::string getText(const unsigned char* p, std::size_t size) {
  std::size_t n = 0;
  while (n < size && p[n] != 0) ++n;
  return std::string(reinterpret_cast<const char*>(p), n);
}

}  // namespace

ReplayHeaderBytes encodeReplayHeader(const ReplayHeader& h) {
  ReplayHeaderBytes b{};
  std::memcpy(b.data(), kReplayMagic.data(), kReplayMagic.size());
  putU32(&b[8], h.formatVersion);
  putU32(&b[12], static_cast<std::uint32_t>(kReplayHeaderSize));
  putU32(&b[16], static_cast<std::uint32_t>(kReplayRecordSize));
  putU32(&b[20], h.flags);
  putF64(&b[24], h.dt);
  putU64(&b[32], h.seed);
  putU64(&b[40], h.tickCount);
  putU64(&b[48], h.firstTick);
  putU64(&b[56], h.checksum);
  putText(&b[64], kReplaySoftwareVersionSize, h.softwareVersion);
  putText(&b[96], kReplayLevelHashSize, h.levelHash);
  putU64(&b[224], h.commandCount);
  putU32(&b[232], static_cast<std::uint32_t>(kReplayCommandSize));
  putText(&b[236], kReplayDeviceKindSize, h.deviceKind);
  return b;
}

std::string decodeReplayHeader(const ReplayHeaderBytes& b, ReplayHeader& h) {
  if (std::memcmp(b.data(), kReplayMagic.data(), kReplayMagic.size()) != 0)
    return "not a hemiroll replay (bad magic at byte 0)";
  h.formatVersion = getU32(&b[8]);
  if (h.formatVersion != kReplayFormatVersion)
    return "replay format version " + std::to_string(h.formatVersion) + ", this build reads version " +
           std::to_string(kReplayFormatVersion);
  if (getU32(&b[12]) != kReplayHeaderSize || getU32(&b[16]) != kReplayRecordSize ||
      getU32(&b[232]) != kReplayCommandSize)
    return "unexpected header or record sizes (bytes 12-19, 232-235)";
  h.flags = getU32(&b[20]);
  h.dt = getF64(&b[24]);
  h.seed = getU64(&b[32]);
  h.tickCount = getU64(&b[40]);
  h.firstTick = getU64(&b[48]);
  h.checksum = getU64(&b[56]);
  h.softwareVersion = getText(&b[64], kReplaySoftwareVersionSize);
  h.levelHash = getText(&b[96], kReplayLevelHashSize);
  h.commandCount = getU64(&b[224]);
  h.deviceKind = getText(&b[236], kReplayDeviceKindSize);
  if (h.deviceKind.empty()) h.deviceKind = "mouse";
  return {};
}

ReplayRecordBytes encodeReplayRecord(const haptics::TickInput& in) {
  ReplayRecordBytes b{};
  putU64(&b[0], in.tick);
  for (int i = 0; i < 3; ++i) putF64(&b[8 + 8 * i], in.position[static_cast<std::size_t>(i)]);
  for (int i = 0; i < 3; ++i) putF64(&b[32 + 8 * i], in.velocity[static_cast<std::size_t>(i)]);
  putU32(&b[56], in.buttons);
  // Bit 0 fresh, bit 1 newPath (files before newPath hold 0 or 1 here).
  b[60] = static_cast<std::uint8_t>((in.fresh ? 1 : 0) | (in.newPath ? 2 : 0));
  putU64(&b[64], static_cast<std::uint64_t>(in.latenessNs));
  return b;
}

haptics::TickInput decodeReplayRecord(const ReplayRecordBytes& b) {
  haptics::TickInput in;
  in.tick = getU64(&b[0]);
  for (int i = 0; i < 3; ++i) in.position[static_cast<std::size_t>(i)] = getF64(&b[8 + 8 * i]);
  for (int i = 0; i < 3; ++i) in.velocity[static_cast<std::size_t>(i)] = getF64(&b[32 + 8 * i]);
  in.buttons = getU32(&b[56]);
  in.fresh = (b[60] & 1) != 0;
  in.newPath = (b[60] & 2) != 0;
  in.latenessNs = static_cast<std::int64_t>(getU64(&b[64]));
  return in;
}

ReplayCommandBytes encodeReplayCommand(const haptics::AppliedCommand& a) {
  ReplayCommandBytes b{};
  const haptics::ServoCommand& c = a.command;
  putU64(&b[0], a.tick);
  putU32(&b[8], static_cast<std::uint32_t>(c.kind));
  putU32(&b[12], static_cast<std::uint32_t>(c.coupling.method));
  putF64(&b[16], c.coupling.stiffness);
  putF64(&b[24], c.coupling.damping);
  putF64(&b[32], c.coupling.alpha);
  b[40] = c.coupling.visualOnly ? 1 : 0;
  for (std::size_t i = 0; i < 12; ++i) putF64(&b[48 + 8 * i], c.state[i]);
  putF64(&b[144], c.time);
  return b;
}

std::string decodeReplayCommand(const ReplayCommandBytes& b, haptics::AppliedCommand& a) {
  const std::uint32_t kind = getU32(&b[8]), method = getU32(&b[12]);
  if (kind > static_cast<std::uint32_t>(haptics::ServoCommandKind::ClearFault))
    return "unknown command kind " + std::to_string(kind);
  if (method > static_cast<std::uint32_t>(physics::ForceMethod::M3)) return "unknown force method " + std::to_string(method);
  if (b[40] > 1) return "bad visualOnly byte";
  haptics::ServoCommand& c = a.command;
  a.tick = getU64(&b[0]);
  c.kind = static_cast<haptics::ServoCommandKind>(kind);
  c.coupling.method = static_cast<physics::ForceMethod>(method);
  c.coupling.stiffness = getF64(&b[16]);
  c.coupling.damping = getF64(&b[24]);
  c.coupling.alpha = getF64(&b[32]);
  c.coupling.visualOnly = b[40] != 0;
  for (std::size_t i = 0; i < 12; ++i) c.state[i] = getF64(&b[48 + 8 * i]);
  c.time = getF64(&b[144]);
  return {};
}

std::uint64_t fnv1a(const unsigned char* data, std::size_t size, std::uint64_t hash) {
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace hemiroll::record
