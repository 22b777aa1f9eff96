#include "engine/haptics/SpscRing.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <thread>

namespace hemiroll::haptics {
namespace {

struct Item {
  std::uint64_t sequence = 0;
  std::array<std::uint64_t, 5> copies{};  // all equal to sequence: a torn item shows
};

TEST(SpscRingTest, FifoAndFullness) {
  SpscRing<int, 4> ring;
  int out = 0;
  EXPECT_FALSE(ring.pop(out));
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(ring.push(i));
  EXPECT_FALSE(ring.push(99));  // full: refused, not blocked, nothing overwritten
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(ring.pop(out));
    EXPECT_EQ(out, i);
  }
  EXPECT_FALSE(ring.pop(out));
}

TEST(SpscRingTest, EveryItemArrivesOnceInOrderUnderConcurrency) {
  SpscRing<Item, 64> ring;
  constexpr std::uint64_t kItems = 200000;
  std::thread producer([&] {
    for (std::uint64_t n = 1; n <= kItems;) {
      Item it;
      it.sequence = n;
      it.copies.fill(n);
      if (ring.push(it)) {
        ++n;
      } else {
        std::this_thread::yield();  // full: let the consumer run (not synchronisation, just courtesy)
      }
    }
  });
  std::uint64_t expected = 1;
  bool ok = true;
  while (expected <= kItems) {
    Item it;
    if (!ring.pop(it)) {
      std::this_thread::yield();
      continue;
    }
    ok &= (it.sequence == expected);
    for (std::uint64_t c : it.copies) ok &= (c == it.sequence);
    ++expected;
  }
  producer.join();
  EXPECT_TRUE(ok);
  Item extra;
  EXPECT_FALSE(ring.pop(extra));
}

}  // namespace
}  // namespace hemiroll::haptics
