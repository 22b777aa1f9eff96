#pragma once
// Where the direction of travel, measured against a path's tangent, passes
// an odd multiple of pi in one sense: the helix's loops (HelixDetector).
// The exact answer is unwrapAngles of atan2 of both directions, their
// difference unwrapped again, and the crossings interpolated; every atan2
// of it is a decision (a step's turn, a crossing's side) except at the
// crossings themselves (issue 32: those atan2 were ~0.2 ms of a 60 s sweep
// point's 1.6 ms). So each decision is taken on a cheap atan2 whose error
// is bounded, and libm's only where the cheap value lies within that bound
// of the decision's boundary: the same positions, to the bit.

#include <cstddef>
#include <span>
#include <vector>

namespace hemiroll::analysis {

// |cheapAtan2(y, x) - std::atan2(y, x)| <= kCheapAtan2Error for finite x, y
// not both zero (one of them infinite too); NaN where both are zero, both
// are infinite or either is NaN.
// Abramowitz & Stegun 4.4.49's polynomial (their 1e-5 is 1.15e-5 with the
// printed coefficients: LoopCrossingsTest scans it, and the error changes by
// less than the scan's spacing between its points, the derivative of the
// difference being under 1).
inline constexpr double kCheapAtan2Error = 2e-5;
double cheapAtan2(double y, double x);

// The tangent's direction (tx, ty) at sample k and the travel's (vx, vy) at
// i are compared at k = min(i < lag ? 0 : i - lag, tangent's last); the
// relative direction, unwrapped, is shifted to start in (-pi, pi]. Returns
// each fractional sample position where it passes the next odd multiple of
// pi in the sense `sense` (+1 or -1; one crossing per sample at most), as
// the exact construction above would, for any input (NaN included: there
// every decision falls back to libm). tx, ty: at least one sample.
std::vector<double> loopCrossings(std::span<const double> tx, std::span<const double> ty,
                                  std::span<const double> vx, std::span<const double> vy, std::size_t lag,
                                  int sense);

}  // namespace hemiroll::analysis
