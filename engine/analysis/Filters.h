#pragma once
// Filters on equally spaced samples (UniformSeries). All are centred (no
// time shift): near the ends the window shrinks symmetrically, so the first
// and last samples are smoothed less rather than pulled towards one side.

#include <span>
#include <vector>

namespace hemiroll::analysis {

// Centred moving average over 2 * halfWidth + 1 samples. It removes a
// sinusoid whose period is the window's length exactly, and attenuates one of
// period P by sinc(pi w / P) (w the window's duration).
std::vector<double> movingAverage(std::span<const double> values, std::size_t halfWidth);

// Samples in a centred window of `duration` seconds: half of (duration / dt)
// rounded, at least 0.
std::size_t halfWidthFor(double duration, double dt);

// Local least-squares slope over 2 * halfWidth + 1 samples (a first-order
// Savitzky-Golay derivative): d(values)/dt. halfWidth 0 is taken as 1.
std::vector<double> localSlope(std::span<const double> values, double dt, std::size_t halfWidth);

// Adds multiples of 2 pi so that no step between neighbours exceeds pi.
std::vector<double> unwrapAngles(std::span<const double> angles);

}  // namespace hemiroll::analysis
