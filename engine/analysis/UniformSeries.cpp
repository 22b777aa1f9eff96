#include "engine/analysis/UniformSeries.h"

#include <algorithm>
#include <cmath>

#include "engine/analysis/Statistics.h"
#include "engine/analysis/Wording.h"

namespace hemiroll::analysis {

UniformSeries resampleUniform(std::span<const double> time, std::span<const std::span<const double>> channels,
                              const ResampleDef& def) {
  UniformSeries out;
  for (const auto& c : channels) {
    if (c.size() != time.size()) {
      out.problem = "the channels are not as long as the time column";
      return out;
    }
  }
  // Usable rows: finite everywhere, time strictly increasing.
  std::vector<std::size_t> rows;
  rows.reserve(time.size());
  for (std::size_t i = 0; i < time.size(); ++i) {
    bool finite = std::isfinite(time[i]);
    for (const auto& c : channels) finite = finite && std::isfinite(c[i]);
    if (!finite || (!rows.empty() && time[i] <= time[rows.back()])) {
      ++out.droppedRows;
      continue;
    }
    rows.push_back(i);
  }
  const auto minSamples = static_cast<std::size_t>(std::max(def.minSamples, 2));
  if (rows.size() < minSamples) {
    out.problem = "only " + std::to_string(rows.size()) + " usable samples (needs " + std::to_string(def.minSamples) +
                  "; non-finite rows are not used)";
    return out;
  }
  // The longest piece between gaps longer than maxGap.
  std::size_t bestFirst = 0, bestLast = 0, first = 0;
  for (std::size_t k = 1; k <= rows.size(); ++k) {
    if (k == rows.size() || time[rows[k]] - time[rows[k - 1]] > def.maxGap) {
      if (time[rows[k - 1]] - time[rows[first]] > time[rows[bestLast]] - time[rows[bestFirst]])
        bestFirst = first, bestLast = k - 1;
      first = k;
    }
  }
  const std::size_t count = bestLast - bestFirst + 1;
  if (count < minSamples) {
    out.problem = "the longest stretch without a gap over " + shortNumber(def.maxGap) + " s" + " has only " +
                  std::to_string(count) + " samples (needs " + std::to_string(def.minSamples) + ")";
    return out;
  }
  std::vector<double> spacing;
  spacing.reserve(count - 1);
  for (std::size_t k = bestFirst + 1; k <= bestLast; ++k) spacing.push_back(time[rows[k]] - time[rows[k - 1]]);
  out.dt = std::max(median(spacing), 1.0 / def.maxRate);
  out.t0 = time[rows[bestFirst]];
  const double span = time[rows[bestLast]] - out.t0;
  // The small allowance keeps the last native sample when span / dt is whole up to round-off.
  const auto n = static_cast<std::size_t>(std::floor(span / out.dt * (1.0 + 1e-12))) + 1;
  if (n < minSamples) {
    out.problem = "only " + shortNumber(span) + " s" + " of usable data (" + std::to_string(n) + " samples at " +
                  shortNumber(out.dt) + " s" + ")";
    return out;
  }
  out.channels.assign(channels.size(), std::vector<double>(n));
  std::size_t k = bestFirst;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = std::min(out.time(i), time[rows[bestLast]]);
    while (k + 1 < bestLast && time[rows[k + 1]] <= t) ++k;
    const std::size_t a = rows[k], b = rows[k + 1];
    const double w = std::clamp((t - time[a]) / (time[b] - time[a]), 0.0, 1.0);
    for (std::size_t c = 0; c < channels.size(); ++c)
      out.channels[c][i] = channels[c][a] * (1.0 - w) + channels[c][b] * w;
  }
  return out;
}

}  // namespace hemiroll::analysis
