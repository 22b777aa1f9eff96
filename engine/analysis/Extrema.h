#pragma once
// Alternating maxima and minima of a sampled signal, found with hysteresis:
// an extremum counts only once the signal has moved away from it by at
// least `delta` (E. Billauer's peakdet rule). Noise smaller than delta
// cannot split one leaf tip into two, and the result always alternates
// max, min, max, ... (or min, max, ...).

#include <span>
#include <vector>

namespace hemiroll::analysis {

struct Extremum {
  double position = 0.0;  // fractional sample index (vertex of a parabola through the three samples around it)
  double value = 0.0;     // the parabola's vertex value
  bool isMaximum = false;
};

std::vector<Extremum> findExtrema(std::span<const double> values, double delta);

}  // namespace hemiroll::analysis
