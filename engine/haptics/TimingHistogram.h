#pragma once
// A fixed-size histogram of durations, written by the servo thread and read
// by anyone at any time: 1 us bins up to kBins us, one overflow bin, and the
// exact maximum. No allocation after construction; the single writer updates
// with relaxed atomic loads and stores (no read-modify-write), so readers see
// each counter whole, and percentiles that may lag the writer by a tick.

#include <array>
#include <atomic>
#include <cstdint>

namespace hemiroll::haptics {

class TimingHistogram {
 public:
  static constexpr int kBins = 5000;           // 1 us each: 0 .. 5 ms
  static constexpr double kBinWidth = 1e-6;    // [s]

  // Writer only. Negative durations count as zero.
  void record(std::int64_t nanoseconds);
  void clear();

  std::uint64_t count() const;
  // The q-quantile (q in [0, 1]) as the upper edge of its bin [s]: never
  // below the true quantile, at most one bin above it. The overflow bin
  // reports the maximum.
  double quantile(double q) const;
  double max() const { return static_cast<double>(maxNs_.load(std::memory_order_relaxed)) * 1e-9; }

 private:
  static void bump(std::atomic<std::uint64_t>& a) {
    a.store(a.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  }
  std::array<std::atomic<std::uint64_t>, kBins + 1> bins_{};
  std::atomic<std::int64_t> maxNs_{0};
};

}  // namespace hemiroll::haptics
