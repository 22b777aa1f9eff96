#include "engine/haptics/TimingHistogram.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::haptics {

void TimingHistogram::record(std::int64_t ns) {
  ns = std::max<std::int64_t>(ns, 0);
  const std::int64_t bin = ns / 1000;
  bump(bins_[static_cast<std::size_t>(std::min<std::int64_t>(bin, kBins))]);
  if (ns > maxNs_.load(std::memory_order_relaxed)) maxNs_.store(ns, std::memory_order_relaxed);
}

void TimingHistogram::clear() {
  for (auto& b : bins_) b.store(0, std::memory_order_relaxed);
  maxNs_.store(0, std::memory_order_relaxed);
}

std::uint64_t TimingHistogram::count() const {
  std::uint64_t n = 0;
  for (const auto& b : bins_) n += b.load(std::memory_order_relaxed);
  return n;
}

double TimingHistogram::quantile(double q) const {
  const std::uint64_t n = count();
  if (n == 0) return 0.0;
  // The rank of the quantile, 1-based: the smallest bin holding it.
  const auto rank = static_cast<std::uint64_t>(std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(n)));
  std::uint64_t seen = 0;
  for (int i = 0; i < kBins; ++i) {
    seen += bins_[static_cast<std::size_t>(i)].load(std::memory_order_relaxed);
    if (seen >= std::max<std::uint64_t>(rank, 1)) return std::min(static_cast<double>(i + 1) * kBinWidth, max());
  }
  return max();
}

}  // namespace hemiroll::haptics
