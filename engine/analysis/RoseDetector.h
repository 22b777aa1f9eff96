#pragma once
// Finds the rose (Svinin et al. 2009, Sec. 4.2 and eqs. 49-50) in the
// mass point's path on the face: the number of leaves per revolution of the
// slow rotation, the leaf radius, the outer radius and the time span over
// which the pattern holds, each with its spread over the leaves.
//
// What is measured, and why it is exact for eqs. (49)-(50): with
// p = r1 e^{i phi} + r2 e^{-i k phi} about the centre c (r1 > r2),
//   |p|^2 = r1^2 + r2^2 + 2 r1 r2 cos((k + 1) phi),
// so the distance rho from the centre swings between r1 - r2 and r1 + r2,
// k + 1 times per turn of phi. A leaf runs from one minimum of rho to the
// next, with its tip at the maximum between. At every minimum
// arg(p) = phi exactly (the second term points straight back), so the angle
// a leaf advances about the centre is 2 pi / (k + 1), and
//   leaves per cycle = 2 pi n / |sum of the n leaves' angles|   -> k + 1,
//   outer radius     = rho at the tips                          -> r1 + r2,
//   leaf radius      = (tip - mean of the two minima) / 2       -> r2,
//   inner radius     = rho at the minima                        -> r1 - r2.
// A path whose leaves enclose the centre (r2 > r1) advances backwards and
// is not reported as a rose; the paper's human data (leaf radius 0.4-1.0 cm,
// outer radius 1.2-2.4 cm) all have r2 < r1.
//
// Steps: resample evenly, smooth over `smoothingTime` (a moving average of
// w seconds shrinks the fast term r2 by sinc(pi w / P), P = 2 pi / (k |Omega|)
// its period in the face frame: a bias of about (pi w / P)^2 / 6 on the leaf
// radius; at 100 Hz the 0.05 s default is 7 samples, 0.07 s, and the bias
// 0.13 % for the paper's rose, 0.4 % for k = 14); centre = the centre
// of the bounding box, then twice the centre of the circle through the leaf
// tips; extrema of rho with hysteresis; the longest run of regular leaves
// (same direction, angle and duration within `regularity` of the run's
// median). Not found, with the reason, when the path is too short or still,
// rho hardly varies (a circle), rho has no clear periodic component (less
// than `minShare` of its variation in one tone above 3 / T: noise),
// the run is shorter than `minLeaves`, or the leaves do not go round the
// centre.

#include <span>
#include <string>
#include <vector>

#include "engine/analysis/PhaseSegmenter.h"
#include "engine/analysis/Statistics.h"
#include "engine/analysis/UniformSeries.h"

namespace hemiroll::analysis {

struct RoseDef {
  double smoothingTime = 0.05;     // [s] moving average of the path
  double hysteresis = 0.3;         // extrema of rho: this fraction of rho's 5-95 % range
  double minModulation = 0.05;     // (q95 - q5) / median of rho below this: no leaves
  double minShare = 0.2;           // rho's leaf tone must hold this share of its variation (DominantTone.h)
  double maxLeafFrequency = 5.0;   // [Hz] searched up to
  double regularity = 0.35;        // a regular leaf's angle and duration: within +-35 % of the run's median
  int minLeaves = 4;               // shortest run of regular leaves that is a rose
  double minLeavesPerCycle = 2.5;  // fewer per revolution: the leaves do not go round the centre
  ResampleDef sampling;
};

struct RoseFeatures {
  bool found = false;
  std::string reason;              // why not found
  double leavesPerCycle = 0.0;     // 2 pi n / |total angle| over the run
  double leavesPerCycleSpread = 0.0;  // standard deviation over the leaves of 2 pi / |angle of the leaf|
  int leaves = 0;                  // leavesPerCycle rounded: the leaves of one closed cycle
  Estimate leafRadius;             // [m]
  Estimate outerRadius;            // [m]
  Estimate innerRadius;            // [m]
  Estimate leafPeriod;             // [s] minimum to minimum
  TimeInterval span;               // first to last minimum of the run
  int leafCount = 0;               // leaves in the run
  double cycles = 0.0;             // revolutions about the centre covered by the run
  int sense = 0;                   // +1: the leaves advance counter-clockwise, -1 clockwise
  std::vector<int> leavesPerClosedCycle;  // leaves counted in each complete revolution
  double centreX = 0.0, centreY = 0.0;    // [m] face coordinates
  double toneShare = 0.0;          // share of rho's variation in its leaf tone
  // 1 for leaves of equal angle covering a full revolution; less when their
  // angles vary (1 - coefficient of variation) or less than a revolution is seen.
  double confidence = 0.0;
  std::vector<double> tipX, tipY;  // [m] the run's leaf tips (for plots)
};

RoseFeatures detectRose(std::span<const double> time, std::span<const double> x, std::span<const double> y,
                        const RoseDef& def = {});
// The same on x and y already resampled by def.sampling (channels 0 and 1).
RoseFeatures detectRose(const UniformSeries& series, const RoseDef& def = {});

}  // namespace hemiroll::analysis
