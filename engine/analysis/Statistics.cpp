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
