#include "engine/haptics/TripleBuffer.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <thread>

namespace hemiroll::haptics {
namespace {

// Every word holds the same counter and the last one its complement: a torn
// read (words from two writes) breaks the invariant.
struct Stamped {
  std::array<std::uint64_t, 31> words{};
  std::uint64_t check = ~std::uint64_t{0};
};

Stamped stamp(std::uint64_t n) {
  Stamped s;
  s.words.fill(n);
  s.check = ~n;
  return s;
}

TEST(TripleBufferTest, EmptyUntilWrittenThenLatestWins) {
  TripleBuffer<Stamped> buffer;
  Stamped out;
  EXPECT_FALSE(buffer.read(out));
  buffer.write(stamp(1));
  buffer.write(stamp(2));
  ASSERT_TRUE(buffer.read(out));
  EXPECT_EQ(out.words[0], 2u);
  ASSERT_TRUE(buffer.read(out));  // nothing new: the same value again
  EXPECT_EQ(out.words[0], 2u);
}

TEST(TripleBufferTest, NoTornReadsAndMonotoneUnderConcurrency) {
  TripleBuffer<Stamped> buffer;
  constexpr std::uint64_t kWrites = 300000;
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (std::uint64_t n = 1; n <= kWrites; ++n) buffer.write(stamp(n));
    done.store(true, std::memory_order_release);
  });
  std::uint64_t last = 0, reads = 0;
  bool torn = false, backwards = false;
  Stamped out;
  while (true) {
    const bool finished = done.load(std::memory_order_acquire);
    if (buffer.read(out)) {
      ++reads;
      for (std::uint64_t w : out.words) torn |= (w != out.words[0]);
      torn |= (out.check != ~out.words[0]);
      backwards |= (out.words[0] < last);
      last = out.words[0];
    }
    if (finished) break;
  }
  writer.join();
  EXPECT_FALSE(torn);
  EXPECT_FALSE(backwards);
  EXPECT_EQ(last, kWrites);  // the read after the writer finished sees the final value
  EXPECT_GT(reads, 0u);
}

}  // namespace
}  // namespace hemiroll::haptics
