#pragma once
// The contact point's trace on the plane (Svinin et al. 2009, Figs. 6 and
// 10: "circularly curved and ... helical"): the arc it follows and the small
// loops along it.
//
//  - Loop frequency: the dominant tone of the trace's complex velocity
//    (DominantTone.h) between 3 / T and `maxLoopFrequency`; a velocity with
//    no clear tone (less than `minShare` of its variation) has no loops.
//  - Arc: the trace low-passed by a moving average over one loop period
//    (which removes a steady loop exactly), its ends (half a period) cut off,
//    and a circle fitted to it (CircleFit.h). Curvature is signed: positive
//    when the arc turns left (counter-clockwise) as the trace advances. Its
//    standard error is Gluckstern's sigma_k = (rms / L^2) sqrt(720 / (N + 4))
//    for N independent points over a chord L, with N = low-passed duration /
//    loop period (samples closer than a period are not independent). The
//    arc is found when |curvature| > 3 sigma_k and the circle explains the
//    bend (rms residual below half the sagitta L^2 |k| / 8): a straight trace
//    is "not curved", with the numbers.
//  - Loops: the direction of travel of the (lightly smoothed) trace,
//    relative to the arc's tangent, unwrapped. A loop turns it once all the
//    way round; a wiggle (a curtate trochoid) never does. A loop is counted
//    when the relative direction first reaches each odd multiple of pi (the
//    moment the point moves backwards, mid-loop), so half loops at the ends
//    do not count. Spacing: time, and arc length along the low-passed trace,
//    between successive loops. Loops whose spacing in time varies by more
//    than `maxSpacingVariation` (std / median) are a tumble, not a helix.
//  - Drift speed: the low-passed trace's length over its duration.

#include <span>
#include <string>
#include <vector>

#include "engine/analysis/PhaseSegmenter.h"
#include "engine/analysis/Statistics.h"
#include "engine/analysis/UniformSeries.h"

namespace hemiroll::analysis {

struct HelixDef {
  double lightSmoothing = 0.05;     // [s] before differentiating the trace
  double maxLoopFrequency = 5.0;    // [Hz]
  double minShare = 0.2;            // the loop tone's share of the velocity's variation
  double fallbackWindow = 2.0;      // [s] low-pass window for the arc when there is no loop tone
  int minLoops = 2;
  double maxSpacingVariation = 0.5; // loops whose spacing in time varies more (std / median) are not a helix
  ResampleDef sampling;
};

struct ArcFeatures {
  bool found = false;
  std::string reason;               // why not curved
  double curvature = 0.0;           // [1/m] signed, + turning counter-clockwise
  double curvatureError = 0.0;      // [1/m] standard error (see above)
  double radius = 0.0;              // [m] 1 / |curvature| (0 for a straight fit)
  double centreX = 0.0, centreY = 0.0;  // [m]
  double rmsResidual = 0.0;         // [m] of the low-passed trace about the circle
  double sweptAngle = 0.0;          // [rad] signed, about the centre, start to end of the low-passed trace
  double length = 0.0;              // [m] of the low-passed trace
  double driftSpeed = 0.0;          // [m/s] length / duration
  TimeInterval span;                // of the low-passed trace
  std::vector<double> x, y;         // [m] the low-passed trace (for plots)
  std::vector<double> along;        // [m] distance along it at each of its samples (from 0; length is the last)
};

struct LoopFeatures {
  bool found = false;
  std::string reason;
  double frequency = 0.0;           // [Hz] of the loop tone (signed: + counter-clockwise)
  double toneShare = 0.0;           // share of the velocity's variation in the loop tone
  int count = 0;                    // complete loops
  int sense = 0;                    // +1 counter-clockwise loops, -1 clockwise
  Estimate spacingTime;             // [s]
  Estimate spacingArc;              // [m] along the low-passed trace
  std::vector<double> times;        // [s] mid-loop instants
  std::vector<double> x, y;         // [m] the trace there (for plots)
};

struct HelixFeatures {
  ArcFeatures arc;
  LoopFeatures loops;
};

HelixFeatures detectHelix(std::span<const double> time, std::span<const double> x, std::span<const double> y,
                          const HelixDef& def = {});
// The same on x and y already resampled by def.sampling (channels 0 and 1).
HelixFeatures detectHelix(const UniformSeries& series, const HelixDef& def = {});

}  // namespace hemiroll::analysis
