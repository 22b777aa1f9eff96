#include "engine/analysis/PhaseSegmenter.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "engine/analysis/Filters.h"
#include "engine/analysis/Statistics.h"
#include "engine/analysis/UniformSeries.h"
#include "engine/analysis/Wording.h"

namespace hemiroll::analysis {

namespace {

struct Run {
  std::size_t first = 0, last = 0;  // inclusive
  std::size_t length() const { return last - first + 1; }
};

// Indices in an array with a moving front: each enters once and leaves
// once, so room for every index serves the whole sweep below (std::deque
// allocates in blocks and reaches each item through its map; a vector's
// push_back holds a call to grow, around which the sweep's loop kept its
// state on the stack: issue 32).
struct IndexQueue {
  explicit IndexQueue(std::size_t capacity) : items(new std::size_t[capacity]) {}
  std::unique_ptr<std::size_t[]> items;
  std::size_t head = 0, tail = 0;
  bool empty() const { return head == tail; }
  std::size_t front() const { return items[head]; }
  std::size_t back() const { return items[tail - 1]; }
  void popFront() { ++head; }
  void popBack() { --tail; }
  void push(std::size_t i) { items[tail++] = i; }
};

// The longest interval whose values all lie within +-(rel |mid| + abs) of
// their mid-range mid. Growing an interval widens its range at least as fast
// as the allowed band (rel < 1), so the two-pointer sweep is exact.
Run longestWithinOwnBand(const std::vector<double>& r, double rel, double abs) {
  Run best;
  IndexQueue maxQ(r.size()), minQ(r.size());  // indices of decreasing maxima / increasing minima
  std::size_t first = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    while (!maxQ.empty() && r[maxQ.back()] <= r[i]) maxQ.popBack();
    while (!minQ.empty() && r[minQ.back()] >= r[i]) minQ.popBack();
    maxQ.push(i), minQ.push(i);
    auto fits = [&] {
      const double hi = r[maxQ.front()], lo = r[minQ.front()];
      return hi - lo <= 2.0 * (rel * std::abs(0.5 * (hi + lo)) + abs);
    };
    while (!fits()) {
      ++first;
      if (maxQ.front() < first) maxQ.popFront();
      if (minQ.front() < first) minQ.popFront();
    }
    if (i - first + 1 > best.length() || i == 0) best = {first, i};
  }
  return best;
}

// The longest run of consecutive samples within band of m.
Run longestWithin(const std::vector<double>& r, double m, double band) {
  Run best{0, 0};
  bool haveBest = false;
  std::size_t first = 0;
  bool inRun = false;
  for (std::size_t i = 0; i <= r.size(); ++i) {
    const bool inside = i < r.size() && std::abs(r[i] - m) <= band;
    if (inside && !inRun) first = i, inRun = true;
    if (!inside && inRun) {
      inRun = false;
      if (!haveBest || i - first > best.length()) best = {first, i - 1}, haveBest = true;
    }
  }
  return best;
}

}  // namespace

Phases segmentPhases(std::span<const double> time, std::span<const double> psi, const PhaseDef& def) {
  Phases out;
  const std::span<const double> channels[] = {psi};
  const UniformSeries series = resampleUniform(time, channels);
  if (!series.ok()) {
    out.reason = "no precession angle to segment: " + series.problem;
    return out;
  }
  out.trial = {series.t0, series.time(series.size() - 1)};
  const std::vector<double> angle = def.unwrap ? unwrapAngles(series.channels[0]) : series.channels[0];
  out.rateT0 = series.t0;
  out.rateDt = series.dt;
  out.rate = movingAverage(localSlope(angle, series.dt, halfWidthFor(def.rateWindow, series.dt)),
                           halfWidthFor(def.rateAverage, series.dt));
  const std::vector<double>& r = out.rate;

  Run run = longestWithinOwnBand(r, def.relativeBand, def.absoluteBand);
  double m = 0.0;
  for (int iteration = 0; iteration < 20; ++iteration) {
    m = median(std::span<const double>(r).subspan(run.first, run.length()));
    const Run next = longestWithin(r, m, def.relativeBand * std::abs(m) + def.absoluteBand);
    if (next.first == run.first && next.last == run.last) break;
    run = next;
  }
  const std::span<const double> steadySamples(r.data() + run.first, run.length());
  const double duration = series.dt * static_cast<double>(run.length() - 1);
  out.steadyRateMedian = m;
  if (std::abs(m) < def.minRate) {
    out.reason = "no steady precession: the longest steady stretch turns at " + shortNumber(m) + " rad/s (below " +
                 shortNumber(def.minRate) + " rad/s)";
    return out;
  }
  if (duration < def.minDuration) {
    out.reason = "no steady precession: the rate stays within " + shortNumber(100.0 * def.relativeBand) +
                 "% of its median for only " + shortNumber(duration) + " s (needs " + shortNumber(def.minDuration) + " s)";
    return out;
  }
  out.found = true;
  out.steady = {series.time(run.first), series.time(run.last)};
  out.acceleration = {out.trial.start, out.steady.start};
  out.deceleration = {out.steady.end, out.trial.end};
  out.steadyRate = duration > 0.0 ? (angle[run.last] - angle[run.first]) / duration : m;
  out.steadyRateSpread = standardDeviation(steadySamples);
  return out;
}

}  // namespace hemiroll::analysis
