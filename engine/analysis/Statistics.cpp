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

double quantile(std::span<const double> values, double q) {
  if (values.empty()) return 0.0;
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  const double at = std::clamp(q, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double w = at - static_cast<double>(below);
  return sorted[below] * (1.0 - w) + sorted[above] * w;
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
