#pragma once
// Filters on equally spaced samples (UniformSeries). All are centred (no
// time shift): near the ends the window shrinks symmetrically, so the first
// and last samples are smoothed less rather than pulled towards one side.

#include <span>
#include <utility>
#include <vector>

namespace hemiroll::analysis {

// Centred moving average over 2 * halfWidth + 1 samples. It removes a
// sinusoid whose period is the window's length exactly, and attenuates one of
// period P by sinc(pi w / P) (w the window's duration).
std::vector<double> movingAverage(std::span<const double> values, std::size_t halfWidth);
// movingAverage of two columns of equal length (a path's x and y), the same
// bits as two calls: their running sums advance side by side, so neither
// waits on the latency of its own chain of additions.
std::pair<std::vector<double>, std::vector<double>> movingAverages(std::span<const double> x,
                                                                   std::span<const double> y, std::size_t halfWidth);

// Samples in a centred window of `duration` seconds: half of (duration / dt)
// rounded, at least 0.
std::size_t halfWidthFor(double duration, double dt);

// Local least-squares slope over 2 * halfWidth + 1 samples (a first-order
// Savitzky-Golay derivative): d(values)/dt. halfWidth 0 is taken as 1.
std::vector<double> localSlope(std::span<const double> values, double dt, std::size_t halfWidth);

// Adds multiples of 2 pi so that no step between neighbours exceeds pi.
std::vector<double> unwrapAngles(std::span<const double> angles);

// The angle a path turns about (cx, cy) from its first point to its last:
// u.back() - u.front() for u = unwrapAngles of the points' atan2 about it,
// to the bit, but with an atan2 only where a step may wrap (issue 32).
double sweptAngleAbout(std::span<const double> x, std::span<const double> y, double cx, double cy);

// What unwrapAngles adds to each point's atan2 about (cx, cy): the angle
// it gives point i is atan2 + offsets[i] (point 0: the atan2 alone), to the
// bit, for a path whose angles are wanted at a few points only (the rose's
// leaf ends); an atan2 only where a step may wrap, as sweptAngleAbout.
std::vector<double> unwrapOffsetsAbout(std::span<const double> x, std::span<const double> y, double cx, double cy);

}  // namespace hemiroll::analysis
