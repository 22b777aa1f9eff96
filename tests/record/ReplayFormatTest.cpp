#include "engine/record/ReplayFormat.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>

namespace hemiroll::record {
namespace {

TEST(ReplayFormatTest, HeaderBytesAreLittleEndianAtTheDocumentedOffsets) {
  ReplayHeader h;
  h.flags = kReplayComplete;
  h.dt = 0.001;
  h.seed = 0x0102030405060708ull;
  h.tickCount = 3;
  h.firstTick = 1;
  h.checksum = 0xA1B2C3D4E5F60718ull;
  h.softwareVersion = "0.1.0";
  h.levelHash = "abc";
  const ReplayHeaderBytes b = encodeReplayHeader(h);
  EXPECT_EQ(std::memcmp(b.data(), "HMRREPLY", 8), 0);
  EXPECT_EQ(b[8], 1);  // format version 1, least significant byte first
  EXPECT_EQ(b[9] | b[10] | b[11], 0);
  EXPECT_EQ(b[12], kReplayHeaderSize & 0xFF);
  EXPECT_EQ(b[13], kReplayHeaderSize >> 8);
  EXPECT_EQ(b[16], kReplayRecordSize);
  EXPECT_EQ(b[32], 0x08);  // seed, least significant byte first
  EXPECT_EQ(b[39], 0x01);
  std::uint64_t dtBits = 0;
  for (int i = 7; i >= 0; --i) dtBits = (dtBits << 8) | b[24 + static_cast<std::size_t>(i)];
  EXPECT_EQ(dtBits, std::bit_cast<std::uint64_t>(0.001));
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&b[64])), "0.1.0");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&b[96])), "abc");

  ReplayHeader back;
  ASSERT_EQ(decodeReplayHeader(b, back), "");
  EXPECT_EQ(back.seed, h.seed);
  EXPECT_EQ(back.checksum, h.checksum);
  EXPECT_EQ(back.dt, h.dt);
  EXPECT_EQ(back.levelHash, "abc");
  EXPECT_EQ(back.deviceKind, "mouse");  // none given: the zeros read as the mouse
}

TEST(ReplayFormatTest, DeviceKindSitsInTheOnceReservedBytes) {
  ReplayHeader h;
  h.deviceKind = "udp";
  ReplayHeaderBytes b = encodeReplayHeader(h);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&b[236])), "udp");
  for (std::size_t i = 252; i < kReplayHeaderSize; ++i) EXPECT_EQ(b[i], 0) << i;
  ReplayHeader back;
  ASSERT_EQ(decodeReplayHeader(b, back), "");
  EXPECT_EQ(back.deviceKind, "udp");
  // A log written before the field existed has zeros there: the mouse.
  for (std::size_t i = 236; i < 252; ++i) b[i] = 0;
  ASSERT_EQ(decodeReplayHeader(b, back), "");
  EXPECT_EQ(back.deviceKind, "mouse");
}

TEST(ReplayFormatTest, RecordsRoundTripBitForBit) {
  haptics::TickInput in;
  in.tick = 123456789;
  in.position = {-0.0, 5e-324, 0.1 + 0.2};
  in.velocity = {1e300, -1.0 / 3.0, 42.0};
  in.buttons = 0x80000001u;
  in.fresh = false;
  in.latenessNs = -3;
  const ReplayRecordBytes b = encodeReplayRecord(in);
  EXPECT_EQ(b[56], 0x01);
  EXPECT_EQ(b[59], 0x80);
  const haptics::TickInput back = decodeReplayRecord(b);
  EXPECT_EQ(back.tick, in.tick);
  EXPECT_EQ(std::memcmp(back.position.data(), in.position.data(), sizeof in.position), 0);
  EXPECT_EQ(std::memcmp(back.velocity.data(), in.velocity.data(), sizeof in.velocity), 0);
  EXPECT_EQ(back.buttons, in.buttons);
  EXPECT_EQ(back.fresh, false);
  EXPECT_EQ(back.newPath, false);
  EXPECT_EQ(back.latenessNs, -3);
}

// Byte 60 holds fresh in bit 0 and newPath in bit 1; a file from before
// newPath has only 0 or 1 there and reads with newPath false.
TEST(ReplayFormatTest, TheFlagsByteKeepsFreshAndNewPathApart) {
  for (const bool fresh : {false, true})
    for (const bool newPath : {false, true}) {
      haptics::TickInput in;
      in.fresh = fresh;
      in.newPath = newPath;
      const ReplayRecordBytes b = encodeReplayRecord(in);
      EXPECT_EQ(b[60], (fresh ? 1 : 0) | (newPath ? 2 : 0));
      const haptics::TickInput back = decodeReplayRecord(b);
      EXPECT_EQ(back.fresh, fresh);
      EXPECT_EQ(back.newPath, newPath);
    }
}

TEST(ReplayFormatTest, CommandsRoundTripBitForBit) {
  haptics::AppliedCommand a;
  a.tick = 77;
  a.command.kind = haptics::ServoCommandKind::ResetState;
  a.command.coupling.method = physics::ForceMethod::M1;
  a.command.coupling.stiffness = 0.1 + 0.2;
  a.command.coupling.visualOnly = true;
  for (std::size_t i = 0; i < 12; ++i) a.command.state[i] = -1.0 / static_cast<double>(i + 3);
  a.command.time = 12.25;
  ReplayCommandBytes b = encodeReplayCommand(a);
  haptics::AppliedCommand back;
  ASSERT_EQ(decodeReplayCommand(b, back), "");
  EXPECT_EQ(back.tick, 77u);
  EXPECT_EQ(back.command.kind, a.command.kind);
  EXPECT_EQ(back.command.coupling.method, physics::ForceMethod::M1);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(back.command.coupling.stiffness), std::bit_cast<std::uint64_t>(0.1 + 0.2));
  EXPECT_TRUE(back.command.coupling.visualOnly);
  EXPECT_EQ(std::memcmp(back.command.state.data(), a.command.state.data(), sizeof a.command.state), 0);
  EXPECT_EQ(back.command.time, 12.25);
  b[8] = 200;  // no such command kind
  EXPECT_EQ(decodeReplayCommand(b, back), "unknown command kind 200");
}

TEST(ReplayFormatTest, WrongMagicOrVersionIsNamed) {
  ReplayHeaderBytes b = encodeReplayHeader(ReplayHeader{});
  ReplayHeader h;
  b[8] = 2;
  EXPECT_EQ(decodeReplayHeader(b, h), "replay format version 2, this build reads version 1");
  b[0] = 'X';
  EXPECT_NE(decodeReplayHeader(b, h).find("not a hemiroll replay"), std::string::npos);
}

TEST(ReplayFormatTest, ChecksumSeesASingleBit) {
  const unsigned char a[4] = {1, 2, 3, 4}, b[4] = {1, 2, 3, 5};
  EXPECT_NE(fnv1a(a, 4, kFnvOffset), fnv1a(b, 4, kFnvOffset));
  EXPECT_EQ(fnv1a(a, 4, kFnvOffset), fnv1a(a + 2, 2, fnv1a(a, 2, kFnvOffset)));  // continues
}

}  // namespace
}  // namespace hemiroll::record
