#include "engine/analysis/Extrema.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::analysis {

namespace {

Extremum refined(std::span<const double> v, std::size_t i, bool isMaximum) {
  Extremum e{static_cast<double>(i), v[i], isMaximum};
  if (i == 0 || i + 1 >= v.size()) return e;
  const double a = v[i - 1], b = v[i], c = v[i + 1];
  const double den = a - 2.0 * b + c;
  if (den == 0.0) return e;
  const double shift = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
  e.position += shift;
  e.value = b - 0.25 * (a - c) * shift;
  return e;
}

// The first extremum is one only if the signal came into it from delta away;
// otherwise it is just where the samples start (or noise near the start).
bool swungInto(std::span<const double> v, std::size_t at, double delta, bool isMaximum) {
  for (std::size_t i = 0; i < at; ++i)
    if (isMaximum ? v[i] <= v[at] - delta : v[i] >= v[at] + delta) return true;
  return false;
}

// The extremes so far: where, and their values (values[maxAt], values[minAt]).
struct Extremes {
  std::size_t maxAt, minAt;
  double maxValue, minValue;
};

// Updates the extremes from sample i on and returns the first sample at
// which the signal has turned by delta the way it is looked for (the end
// if none). Held as values, in registers in a loop without calls (issue
// 32: read through the index, or from the stack where the loop held calls,
// each sample waited on the previous one's load); the same comparisons as
// one loop over every sample, so the same extrema. Not inlined: GCC would
// then keep the extremes on the stack for the calls around it.
[[gnu::noinline]] std::size_t scanToTurn(std::span<const double> values, std::size_t i, int looking, double delta,
                                          Extremes& at) {
  Extremes e = at;
  for (; i < values.size(); ++i) {
    const double v = values[i];
    if (v > e.maxValue) e.maxAt = i, e.maxValue = v;
    if (v < e.minValue) e.minAt = i, e.minValue = v;
    if ((looking >= 0 && v < e.maxValue - delta) || (looking <= 0 && v > e.minValue + delta)) break;
  }
  at = e;
  return i;
}

}  // namespace

std::vector<Extremum> findExtrema(std::span<const double> values, double delta) {
  std::vector<Extremum> out;
  if (values.size() < 3 || !(delta > 0.0)) return out;
  Extremes e{0, 0, values[0], values[0]};
  int looking = 0;  // +1 for a maximum, -1 for a minimum, 0 not yet decided
  for (std::size_t i = scanToTurn(values, 1, looking, delta, e); i < values.size();
       i = scanToTurn(values, i + 1, looking, delta, e)) {
    if (looking >= 0 && values[i] < e.maxValue - delta) {
      if (looking > 0 || swungInto(values, e.maxAt, delta, true)) out.push_back(refined(values, e.maxAt, true));
      looking = -1;
      e.minAt = i, e.minValue = values[i];
    } else {
      if (looking < 0 || swungInto(values, e.minAt, delta, false)) out.push_back(refined(values, e.minAt, false));
      looking = 1;
      e.maxAt = i, e.maxValue = values[i];
    }
  }
  return out;
}

}  // namespace hemiroll::analysis
