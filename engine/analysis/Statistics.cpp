#include "engine/analysis/Statistics.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::analysis {

double mean(std::span<const double> values) {
  if (values.empty()) return 0.0;
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

// The two order statistics by selection, not by sorting (issue 32: the
// sort was 6-9 % of a sweep point): nth_element puts the one below in
// place, and the one above is the smallest of what lies after it. The same
// two values as a sort's, so the same result to the bit.
double quantile(std::span<const double> values, double q) {
  if (values.empty()) return 0.0;
  std::vector<double> work(values.begin(), values.end());
  const double at = std::clamp(q, 0.0, 1.0) * static_cast<double>(work.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, work.size() - 1);
  const double w = at - static_cast<double>(below);
  std::nth_element(work.begin(), work.begin() + static_cast<std::ptrdiff_t>(below), work.end());
  const double low = work[below];
  const double high = above == below ? low : *std::min_element(work.begin() + static_cast<std::ptrdiff_t>(above), work.end());
  return low * (1.0 - w) + high * w;
}

// From the highest rank down: after the selection of rank b within [0, end),
// [0, b) holds what lies below it and (b, end) what lies above, and
// everything from `end` on is at least work[end] (the previous rank's
// value), so the value at rank b + 1 is the least of (b, end] (the sort's).
std::vector<double> quantiles(std::span<const double> values, std::span<const double> qs) {
  std::vector<double> out(qs.size(), 0.0);
  if (values.empty()) return out;
  std::vector<double> work(values.begin(), values.end());
  const std::size_t n = work.size();
  struct Rank {
    std::size_t q, below, above;
    double w;
  };
  std::vector<Rank> ranks;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    const double at = std::clamp(qs[i], 0.0, 1.0) * static_cast<double>(n - 1);
    const auto below = static_cast<std::size_t>(std::floor(at));
    ranks.push_back({i, below, std::min(below + 1, n - 1), at - static_cast<double>(below)});
  }
  std::sort(ranks.begin(), ranks.end(), [](const Rank& a, const Rank& b) { return a.below > b.below; });
  std::size_t end = n;
  double low = 0.0, high = 0.0;
  for (const Rank& r : ranks) {
    if (r.below < end) {
      const auto first = work.begin();
      std::nth_element(first, first + static_cast<std::ptrdiff_t>(r.below), first + static_cast<std::ptrdiff_t>(end));
      low = work[r.below];
      if (r.above == r.below) {
        high = low;
      } else {
        const std::size_t last = std::min(end, n - 1);  // (b, end], within the values
        high = *std::min_element(first + static_cast<std::ptrdiff_t>(r.above), first + static_cast<std::ptrdiff_t>(last) + 1);
      }
      end = r.below;
    }  // else: the same rank as the one before, whose low and high stand
    out[r.q] = low * (1.0 - r.w) + high * r.w;
  }
  return out;
}

double median(std::span<const double> values) { return quantile(values, 0.5); }

double standardDeviation(std::span<const double> values) {
  if (values.size() < 2) return 0.0;
  const double m = mean(values);
  double sum = 0.0;
  for (double v : values) sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

Estimate summarize(std::span<const double> values) {
  return {median(values), standardDeviation(values), static_cast<int>(values.size())};
}

}  // namespace hemiroll::analysis
