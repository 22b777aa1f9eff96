// Fuzz target: a UDP bridge datagram (engine/haptics/UdpProtocol), both
// directions. A datagram that decodes must encode to bytes that decode
// again to the same bytes (a value survives the round trip).
#include <array>
#include <cstdlib>

#include "engine/haptics/UdpProtocol.h"
#include "tests/fuzz/FuzzInput.h"

namespace {

template <typename Message, std::size_t Size, typename Decode, typename Encode>
void roundTrip(const std::uint8_t* data, std::size_t size, Decode decode, Encode encode) {
  Message first;
  if (decode(data, size, first) != hemiroll::haptics::udp::DecodeError::None) return;
  std::array<std::uint8_t, Size> once{}, twice{};
  encode(first, once.data());
  Message second;
  if (decode(once.data(), once.size(), second) != hemiroll::haptics::udp::DecodeError::None) std::abort();
  encode(second, twice.data());
  if (once != twice) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hemiroll::haptics::udp;
  roundTrip<StateMessage, kStateSize>(data, size, decodeState, encodeState);
  roundTrip<ForceMessage, kForceSize>(data, size, decodeForce, encodeForce);
  return 0;
}
