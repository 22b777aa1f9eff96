#pragma once
// The replay log's binary layout (version 1), little-endian on every host:
// a 256-byte header, one 72-byte input record per servo tick, then one
// 160-byte command record per command the loop applied.
//
// header  offset size
//   magic            0   8  "HMRREPLY"
//   formatVersion    8   4  u32, 1
//   headerSize      12   4  u32, 256
//   recordSize      16   4  u32, 64
//   flags           20   4  u32, bit 0: complete (set by finish)
//   dt              24   8  f64, servo period [s]
//   seed            32   8  u64
//   tickCount       40   8  u64, records that follow
//   firstTick       48   8  u64, the first record's tick
//   checksum        56   8  u64, FNV-1a 64 of all record bytes
//   softwareVersion 64  32  ASCII, NUL padded
//   levelHash       96 128  ASCII, NUL padded
//   commandCount   224   8  u64, command records after the inputs
//   commandSize    232   4  u32, 160
//   deviceKind     236  16  ASCII, NUL padded ("" = mouse: the zeros of
//                           logs written before the field existed)
//   reserved       252   4  zero
// input record (checksummed, then the command records)
//   tick             0   8  u64 (consecutive)
//   position         8  24  3 x f64, device frame [m]
//   velocity        32  24  3 x f64 [m/s]
//   buttons         56   4  u32
//   fresh           60   1  u8, 0 or 1
//   padding         61   3  zero
//   latenessNs      64   8  i64, the tick's lateness [ns]
// command record
//   tick             0   8  u64, applied at the start of this tick
//   kind             8   4  u32, ServoCommandKind
//   method          12   4  u32, ForceMethod (SetCoupling)
//   stiffness       16   8  f64 [N/m]
//   damping         24   8  f64 [N s/m]
//   alpha           32   8  f64 [-]
//   visualOnly      40   1  u8; 41..47 zero
//   state           48  96  12 x f64 (ResetState)
//   time           144   8  f64 [s] (ResetState)
//   padding        152   8  zero

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/haptics/RecordRow.h"

namespace hemiroll::record {

inline constexpr std::array<char, 8> kReplayMagic = {'H', 'M', 'R', 'R', 'E', 'P', 'L', 'Y'};
inline constexpr std::uint32_t kReplayFormatVersion = 1;
inline constexpr std::size_t kReplayHeaderSize = 256;
inline constexpr std::size_t kReplayRecordSize = 72;
inline constexpr std::size_t kReplayCommandSize = 160;
inline constexpr std::uint32_t kReplayComplete = 1u;
inline constexpr std::size_t kReplaySoftwareVersionSize = 32;
inline constexpr std::size_t kReplayLevelHashSize = 128;
inline constexpr std::size_t kReplayDeviceKindSize = 16;

struct ReplayHeader {
  std::uint32_t formatVersion = kReplayFormatVersion;
  std::uint32_t flags = 0;
  double dt = 0.001;
  std::uint64_t seed = 0;
  std::uint64_t tickCount = 0;
  std::uint64_t firstTick = 1;
  std::uint64_t checksum = 0;
  std::uint64_t commandCount = 0;
  std::string softwareVersion;  // at most 31 characters
  std::string levelHash;        // at most 127 characters
  std::string deviceKind;       // at most 15 characters; "" reads as "mouse"
};

using ReplayHeaderBytes = std::array<unsigned char, kReplayHeaderSize>;
using ReplayRecordBytes = std::array<unsigned char, kReplayRecordSize>;
using ReplayCommandBytes = std::array<unsigned char, kReplayCommandSize>;

ReplayHeaderBytes encodeReplayHeader(const ReplayHeader& h);
// Empty when it decoded, else what is wrong (magic, version, sizes).
std::string decodeReplayHeader(const ReplayHeaderBytes& bytes, ReplayHeader& h);
ReplayRecordBytes encodeReplayRecord(const haptics::TickInput& in);
haptics::TickInput decodeReplayRecord(const ReplayRecordBytes& bytes);
ReplayCommandBytes encodeReplayCommand(const haptics::AppliedCommand& c);
// Empty when it decoded, else what is wrong (an unknown kind or method).
std::string decodeReplayCommand(const ReplayCommandBytes& bytes, haptics::AppliedCommand& c);
// FNV-1a 64, continued from `hash` (start with kFnvOffset).
inline constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
std::uint64_t fnv1a(const unsigned char* data, std::size_t size, std::uint64_t hash);

}  // namespace hemiroll::record
