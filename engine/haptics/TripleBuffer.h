#pragma once
// Latest-value hand-over from one writer thread to one reader thread, lock
// free and wait free: three slots; the writer fills its back slot and swaps
// it with the middle one; the reader swaps the middle one into its front slot
// when it holds something new. Each slot is touched by one thread at a time,
// so a read is never torn, and neither side ever waits for the other. Older
// values the reader did not take are dropped (latest wins).

#include <array>
#include <atomic>
#include <cstdint>
#include <type_traits>

namespace hemiroll::haptics {

template <typename T>
class TripleBuffer {
  static_assert(std::is_trivially_copyable_v<T>, "TripleBuffer copies values as plain bytes");

 public:
  // Writer thread only.
  void write(const T& value) {
    slots_[back_].value = value;
    back_ = static_cast<std::uint8_t>(middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex);
  }

  // Reader thread only. Copies the newest value into out; false while
  // nothing has been written yet.
  bool read(T& out) {
    if (middle_.load(std::memory_order_relaxed) & kFresh) {
      front_ = static_cast<std::uint8_t>(middle_.exchange(front_, std::memory_order_acq_rel) & kIndex);
      hasValue_ = true;
    }
    if (!hasValue_) return false;
    out = slots_[front_].value;
    return true;
  }

 private:
  static constexpr std::uint8_t kIndex = 0x3, kFresh = 0x4;
  // Each slot on its own cache lines, so the two threads do not share lines.
  struct alignas(64) Slot {
    T value{};
  };
  std::array<Slot, 3> slots_{};
  alignas(64) std::atomic<std::uint8_t> middle_{0};
  alignas(64) std::uint8_t back_ = 1;  // writer's
  alignas(64) std::uint8_t front_ = 2;  // reader's
  bool hasValue_ = false;
};

}  // namespace hemiroll::haptics
