#include "engine/haptics/UdpProtocol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace hemiroll::haptics::udp {
namespace {

StateMessage sampleState() {
  StateMessage m;
  m.sequence = 0xA1B2C3D4;
  m.timestampNs = 0x0102030405060708ull;
  m.position = {0.0123, -0.0456, 1e-300};
  m.velocity = {-0.5, 0.25, -0.0};
  m.buttons = 0x80000005;
  m.deviceStatus = 7;
  return m;
}

ForceMessage sampleForce() {
  ForceMessage m;
  m.sequence = 42;
  m.answers = 0xFFFFFFFF;
  m.echoTimestampNs = 987654321012345ull;
  m.force = {1.5, -2.75, 3.0e-9};
  m.status = BridgeStatus::Stale;
  return m;
}

std::vector<std::uint8_t> encoded(const StateMessage& m) {
  std::vector<std::uint8_t> b(kStateSize);
  EXPECT_EQ(encodeState(m, b.data()), kStateSize);
  return b;
}

TEST(UdpProtocolTest, StateRoundTripIsExact) {
  const StateMessage in = sampleState();
  const std::vector<std::uint8_t> b = encoded(in);
  StateMessage out;
  ASSERT_EQ(decodeState(b.data(), b.size(), out), DecodeError::None);
  EXPECT_EQ(out.sequence, in.sequence);
  EXPECT_EQ(out.timestampNs, in.timestampNs);
  EXPECT_EQ(out.buttons, in.buttons);
  EXPECT_EQ(out.deviceStatus, in.deviceStatus);
  // Bit patterns, so that -0.0 and denormal-range values survive too.
  EXPECT_EQ(std::memcmp(out.position.data(), in.position.data(), sizeof in.position), 0);
  EXPECT_EQ(std::memcmp(out.velocity.data(), in.velocity.data(), sizeof in.velocity), 0);
}

TEST(UdpProtocolTest, ForceRoundTripIsExact) {
  const ForceMessage in = sampleForce();
  std::uint8_t b[kForceSize];
  ASSERT_EQ(encodeForce(in, b), kForceSize);
  ForceMessage out;
  ASSERT_EQ(decodeForce(b, kForceSize, out), DecodeError::None);
  EXPECT_EQ(out.sequence, in.sequence);
  EXPECT_EQ(out.answers, in.answers);
  EXPECT_EQ(out.echoTimestampNs, in.echoTimestampNs);
  EXPECT_EQ(out.status, in.status);
  EXPECT_EQ(std::memcmp(out.force.data(), in.force.data(), sizeof in.force), 0);
}

// The layout in docs/UDP_BRIDGE.md, byte by byte: little-endian at the
// documented offsets, whatever the host.
TEST(UdpProtocolTest, StateBytesAreAtTheDocumentedOffsets) {
  const std::vector<std::uint8_t> b = encoded(sampleState());
  EXPECT_EQ(std::vector<std::uint8_t>(b.begin(), b.begin() + 4), (std::vector<std::uint8_t>{'H', 'R', 'O', 'L'}));
  EXPECT_EQ(b[4], kVersion);
  EXPECT_EQ(b[5], 1);                     // type: state
  EXPECT_EQ(b[6] | (b[7] << 8), 76);      // size
  EXPECT_EQ(b[8], 0xD4);                  // sequence, least significant byte first
  EXPECT_EQ(b[11], 0xA1);
  EXPECT_EQ(b[12], 0x08);                 // timestamp
  EXPECT_EQ(b[19], 0x01);
  double x = 0.0;                         // position x at 20 as IEEE 754 binary64
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= std::uint64_t{b[static_cast<std::size_t>(20 + i)]} << (8 * i);
  std::memcpy(&x, &bits, 8);
  EXPECT_EQ(x, 0.0123);
  EXPECT_EQ(b[68], 0x05);                 // buttons
  EXPECT_EQ(b[71], 0x80);
  EXPECT_EQ(b[72], 7);                    // device status
  EXPECT_EQ(b[73] | b[74] | b[75], 0);    // reserved
}

TEST(UdpProtocolTest, ForceBytesAreAtTheDocumentedOffsets) {
  std::uint8_t b[kForceSize];
  encodeForce(sampleForce(), b);
  EXPECT_EQ(b[5], 2);
  EXPECT_EQ(b[6] | (b[7] << 8), 52);
  EXPECT_EQ(b[8], 42);
  EXPECT_EQ(b[12] & b[13] & b[14] & b[15], 0xFF);  // answers
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= std::uint64_t{b[24 + i]} << (8 * i);
  double fx = 0.0;
  std::memcpy(&fx, &bits, 8);
  EXPECT_EQ(fx, 1.5);
  EXPECT_EQ(b[48], 1);  // status: stale
}

TEST(UdpProtocolTest, EveryMalformedStateIsRejectedAndLeavesOutputAlone) {
  const std::vector<std::uint8_t> good = encoded(sampleState());
  struct Case {
    const char* what;
    std::vector<std::uint8_t> bytes;
    DecodeError expected;
  };
  std::vector<Case> cases;
  cases.push_back({"empty", {}, DecodeError::TooShort});
  cases.push_back({"11 bytes", std::vector<std::uint8_t>(good.begin(), good.begin() + 11), DecodeError::TooShort});
  auto modified = [&](std::size_t at, std::uint8_t value) {
    std::vector<std::uint8_t> b = good;
    b[at] = value;
    return b;
  };
  cases.push_back({"magic", modified(0, 'X'), DecodeError::BadMagic});
  cases.push_back({"version 2", modified(4, 2), DecodeError::BadVersion});
  cases.push_back({"version 0", modified(4, 0), DecodeError::BadVersion});
  cases.push_back({"type force", modified(5, 2), DecodeError::BadType});
  cases.push_back({"type 9", modified(5, 9), DecodeError::BadType});
  cases.push_back({"truncated", std::vector<std::uint8_t>(good.begin(), good.end() - 1), DecodeError::SizeMismatch});
  std::vector<std::uint8_t> longer = good;
  longer.push_back(0);
  cases.push_back({"one byte extra", longer, DecodeError::SizeMismatch});
  // Header and datagram agree on 77 bytes, but a state is 76.
  std::vector<std::uint8_t> consistentButWrong = longer;
  consistentButWrong[6] = 77;
  cases.push_back({"wrong size for type", consistentButWrong, DecodeError::BadSize});
  std::vector<std::uint8_t> nanPosition = good;
  const std::uint64_t nanBits = 0x7FF8000000000000ull;
  for (int i = 0; i < 8; ++i) nanPosition[static_cast<std::size_t>(28 + i)] = static_cast<std::uint8_t>(nanBits >> (8 * i));
  cases.push_back({"NaN position y", nanPosition, DecodeError::NonFinite});
  std::vector<std::uint8_t> infVelocity = good;
  const std::uint64_t infBits = 0x7FF0000000000000ull;
  for (int i = 0; i < 8; ++i) infVelocity[static_cast<std::size_t>(60 + i)] = static_cast<std::uint8_t>(infBits >> (8 * i));
  cases.push_back({"Inf velocity z", infVelocity, DecodeError::NonFinite});

  for (const Case& c : cases) {
    StateMessage out;
    out.sequence = 99;
    EXPECT_EQ(decodeState(c.bytes.data(), c.bytes.size(), out), c.expected) << c.what;
    EXPECT_EQ(out.sequence, 99u) << c.what << ": output written on failure";
    EXPECT_STRNE(decodeErrorName(c.expected), "?") << c.what;
  }
}

TEST(UdpProtocolTest, MalformedForcesAreRejected) {
  std::uint8_t b[kForceSize];
  encodeForce(sampleForce(), b);
  ForceMessage out;
  EXPECT_EQ(decodeForce(b, kForceSize - 1, out), DecodeError::SizeMismatch);
  b[5] = 1;  // a state's type on a force's bytes
  EXPECT_EQ(decodeForce(b, kForceSize, out), DecodeError::BadType);
  b[5] = 2;
  const std::uint64_t nanBits = 0x7FF8000000000001ull;
  for (int i = 0; i < 8; ++i) b[40 + i] = static_cast<std::uint8_t>(nanBits >> (8 * i));
  EXPECT_EQ(decodeForce(b, kForceSize, out), DecodeError::NonFinite);
}

TEST(UdpProtocolTest, SequenceOrderSurvivesWrapAround) {
  EXPECT_TRUE(sequenceAfter(2, 1));
  EXPECT_FALSE(sequenceAfter(1, 2));
  EXPECT_FALSE(sequenceAfter(5, 5));  // a duplicate is not new
  EXPECT_TRUE(sequenceAfter(0, 0xFFFFFFFF));
  EXPECT_TRUE(sequenceAfter(3, 0xFFFFFFF0));
  EXPECT_FALSE(sequenceAfter(0xFFFFFFF0, 3));
}

}  // namespace
}  // namespace hemiroll::haptics::udp
