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

}  // namespace

std::vector<Extremum> findExtrema(std::span<const double> values, double delta) {
  std::vector<Extremum> out;
  if (values.size() < 3 || !(delta > 0.0)) return out;
  std::size_t maxAt = 0, minAt = 0;
  int looking = 0;  // +1 for a maximum, -1 for a minimum, 0 not yet decided
  for (std::size_t i = 1; i < values.size(); ++i) {
    if (values[i] > values[maxAt]) maxAt = i;
    if (values[i] < values[minAt]) minAt = i;
    if (looking >= 0 && values[i] < values[maxAt] - delta) {
      if (looking > 0 || swungInto(values, maxAt, delta, true)) out.push_back(refined(values, maxAt, true));
      looking = -1;
      minAt = i;
    } else if (looking <= 0 && values[i] > values[minAt] + delta) {
      if (looking < 0 || swungInto(values, minAt, delta, false)) out.push_back(refined(values, minAt, false));
      looking = 1;
      maxAt = i;
    }
  }
  return out;
}

}  // namespace hemiroll::analysis
