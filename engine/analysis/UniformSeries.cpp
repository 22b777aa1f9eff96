#include "engine/analysis/UniformSeries.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

#include "engine/analysis/Statistics.h"
#include "engine/analysis/Wording.h"

namespace hemiroll::analysis {

namespace {

// Eight values at a time in four of SSE2's pairs (every x86-64), without a
// branch (issue 32: the row-by-row test, channel by channel, had been most
// of a resampling's time; the simulator's rows are all usable). Plain
// comparisons: no value is computed from them.
typedef double Pair __attribute__((vector_size(2 * sizeof(double))));
typedef long long PairFlags __attribute__((vector_size(2 * sizeof(long long))));
constexpr std::size_t kPairs = 4;

bool noneSet(const PairFlags (&flags)[kPairs]) {
  PairFlags any = flags[0] | flags[1] | flags[2] | flags[3];
  return (any[0] | any[1]) == 0;
}

// Every row usable: every value finite (x - x is 0 for a finite x, NaN for
// an infinite or NaN one), each time above the one before (between two
// finite ends, every time is then finite). All columns in one pass, so
// that their streams from memory overlap: the columns are read here first,
// from farther than the caches, and one column after another had waited
// on each in turn.
bool allRowsUsable(std::span<const double> t, std::span<const std::span<const double>> channels) {
  const std::size_t n = t.size();
  if (n == 0) return true;
  if (!(t.front() - t.front() == 0.0) || !(t.back() - t.back() == 0.0)) return false;
  PairFlags bad[kPairs] = {};
  std::size_t i = 0;
  for (; i + 2 * kPairs + 1 <= n; i += 2 * kPairs) {  // rows i .. i + 7, times up to i + 8
    for (std::size_t p = 0; p < kPairs; ++p) {
      Pair before, after;
      std::memcpy(&before, t.data() + i + 2 * p, sizeof before);
      std::memcpy(&after, t.data() + i + 2 * p + 1, sizeof after);
      bad[p] |= ~(before < after);
    }
    for (const auto& c : channels) {
      for (std::size_t p = 0; p < kPairs; ++p) {
        Pair x;
        std::memcpy(&x, c.data() + i + 2 * p, sizeof x);
        bad[p] |= ~(x - x == 0.0);
      }
    }
  }
  bool ok = noneSet(bad);
  for (; i < n; ++i) {
    ok = ok && (i + 1 == n || t[i] < t[i + 1]);
    for (const auto& c : channels) ok = ok && c[i] - c[i] == 0.0;
  }
  return ok;
}

// The grid's spacing, max(median native spacing, 1 / maxRate), over the
// rows row(first) .. row(last). Where more than half the spacings lie below
// 1 / maxRate (data at or above the maximum rate, as the simulator's 100 Hz
// rows are), the median, whatever it is, lies below it too: the two order
// statistics it is made of do, and low (1 - w) + high w with w 0 or 1/2
// is at most high (halving is exact above 2 DBL_MIN, and a smaller high
// gives at most 2 DBL_MIN); so the count alone decides and no selection is
// needed (issue 32: two per sweep point).
template <class Row>
double gridSpacing(std::span<const double> time, Row row, std::size_t first, std::size_t last, const ResampleDef& def) {
  const double fastest = 1.0 / def.maxRate;
  const std::size_t m = last - first;  // spacings, at least 1
  std::size_t below = 0;
  for (std::size_t k = first + 1; k <= last; ++k) below += time[row(k)] - time[row(k - 1)] < fastest;
  const std::size_t above = std::min((m - 1) / 2 + 1, m - 1);  // quantile's ranks of the median
  if (below > above && fastest > 2.0 * DBL_MIN) return fastest;
  std::vector<double> spacing;
  spacing.reserve(m);
  for (std::size_t k = first + 1; k <= last; ++k) spacing.push_back(time[row(k)] - time[row(k - 1)]);
  return std::max(median(spacing), fastest);
}

// The rest of resampleUniform, on the usable rows row(0) .. row(count - 1).
template <class Row>
UniformSeries fromRows(std::span<const double> time, std::span<const std::span<const double>> channels, Row row,
                       std::size_t count, UniformSeries out, const ResampleDef& def) {
  const auto minSamples = static_cast<std::size_t>(std::max(def.minSamples, 2));
  if (count < minSamples) {
    out.problem = "only " + std::to_string(count) + " usable samples (needs " + std::to_string(def.minSamples) +
                  "; non-finite rows are not used)";
    return out;
  }
  // The longest piece between gaps longer than maxGap.
  std::size_t bestFirst = 0, bestLast = 0, first = 0;
  for (std::size_t k = 1; k <= count; ++k) {
    if (k == count || time[row(k)] - time[row(k - 1)] > def.maxGap) {
      if (time[row(k - 1)] - time[row(first)] > time[row(bestLast)] - time[row(bestFirst)])
        bestFirst = first, bestLast = k - 1;
      first = k;
    }
  }
  const std::size_t kept = bestLast - bestFirst + 1;
  if (kept < minSamples) {
    out.problem = "the longest stretch without a gap over " + shortNumber(def.maxGap) + " s" + " has only " +
                  std::to_string(kept) + " samples (needs " + std::to_string(def.minSamples) + ")";
    return out;
  }
  out.dt = gridSpacing(time, row, bestFirst, bestLast, def);
  out.t0 = time[row(bestFirst)];
  const double tLast = time[row(bestLast)];
  const double span = tLast - out.t0;
  // The small allowance keeps the last native sample when span / dt is whole up to round-off.
  const auto n = static_cast<std::size_t>(std::floor(span / out.dt * (1.0 + 1e-12))) + 1;
  if (n < minSamples) {
    out.problem = "only " + shortNumber(span) + " s" + " of usable data (" + std::to_string(n) + " samples at " +
                  shortNumber(out.dt) + " s" + ")";
    return out;
  }
  out.channels.assign(channels.size(), std::vector<double>(n));
  // Held in locals: a store to a channel might otherwise be the grid's t0 or dt.
  const double t0 = out.t0, dt = out.dt;
  std::vector<const double*> from;
  std::vector<double*> to;
  for (std::size_t c = 0; c < channels.size(); ++c) from.push_back(channels[c].data()), to.push_back(out.channels[c].data());
  std::size_t k = bestFirst;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = std::min(t0 + static_cast<double>(i) * dt, tLast);
    // The last row at or before t, k + 1 < bestLast: a step of one without
    // a branch (at 100 Hz the grid falls just before or on a row, as round-
    // off has it), any longer run of rows (denser data) by the loop first.
    while (k + 2 < bestLast && time[row(k + 2)] <= t) ++k;
    k += static_cast<std::size_t>(k + 1 < bestLast) & static_cast<std::size_t>(time[row(k + 1)] <= t);
    const std::size_t a = row(k), b = row(k + 1);
    const double w = std::clamp((t - time[a]) / (time[b] - time[a]), 0.0, 1.0);
    for (std::size_t c = 0; c < from.size(); ++c) to[c][i] = from[c][a] * (1.0 - w) + from[c][b] * w;
  }
  return out;
}

}  // namespace

UniformSeries resampleUniform(std::span<const double> time, std::span<const std::span<const double>> channels,
                              const ResampleDef& def) {
  UniformSeries out;
  for (const auto& c : channels) {
    if (c.size() != time.size()) {
      out.problem = "the channels are not as long as the time column";
      return out;
    }
  }
  if (allRowsUsable(time, channels)) return fromRows(time, channels, [](std::size_t k) { return k; }, time.size(), std::move(out), def);
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
  return fromRows(time, channels, [&rows](std::size_t k) { return rows[k]; }, rows.size(), std::move(out), def);
}

}  // namespace hemiroll::analysis
