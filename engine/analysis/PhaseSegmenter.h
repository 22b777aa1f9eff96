#pragma once
// The three phases of a trial (Svinin et al. 2009, Sec. 4.2 and 5: "the
// acceleration, the steady state precession, and the deceleration/
// stabilization phases"), found from the precession angle psi(t).
//
// Definitions (docs/ANALYSIS.md):
//  - rate: psi'(t) by a local least-squares slope over `rateWindow` seconds
//    of the (unwrapped) angle, then a moving average over `rateAverage`
//    seconds. Each leaf of the rose puts a wobble on psi (2.2 s in the
//    paper's actuation, Fig. 11; ~2 s in the human data), which would split
//    the steady phase; the two stages together (6 s of support) pass less
//    than 5 % of it, where one 5 s slope passed 20 %. For a quadratic psi
//    (a constant acceleration) both stages are exact away from the ends;
//  - steady precession: the longest interval on which the rate stays within
//    +-(relativeBand |m| + absoluteBand) of m, where m is the median rate
//    over that same interval. It is found as a fixed point: start from the
//    longest interval whose rate range fits such a band about its own
//    mid-range (exact, two pointers), then take its median and the longest
//    run within the band about it, until the interval stops changing;
//  - acceleration: from the start to the steady phase; deceleration/
//    stabilisation: from its end to the end (either may be empty).
// Not found, with the reason, when |m| < minRate (no precession) or the
// interval is shorter than minDuration.
// The rate is smoothed over rateWindow + rateAverage, so a boundary between
// phases is located to about half of that plus the band's share of a ramp.

#include <span>
#include <string>
#include <vector>

namespace hemiroll::analysis {

struct TimeInterval {
  double start = 0.0;  // [s]
  double end = 0.0;    // [s]
  double duration() const { return end - start; }
};

struct PhaseDef {
  double rateWindow = 3.0;      // [s] slope window for psi'
  double rateAverage = 3.0;     // [s] then a moving average of the slope over this window
  double relativeBand = 0.25;   // [-] steady: within this fraction of |m| ...
  double absoluteBand = 0.02;   // [rad/s] ... plus this
  double minRate = 0.05;        // [rad/s] a slower median is no precession
  double minDuration = 3.0;     // [s] shortest steady phase
  bool unwrap = true;           // psi from a source that wraps it into (-pi, pi]
};

struct Phases {
  bool found = false;
  std::string reason;                 // why not found
  TimeInterval trial;                 // the analysed samples' span
  TimeInterval acceleration, steady, deceleration;
  double steadyRate = 0.0;            // [rad/s] mean rate over the steady phase: its change of psi / its duration
  double steadyRateMedian = 0.0;      // [rad/s] m
  double steadyRateSpread = 0.0;      // [rad/s] standard deviation of the smoothed rate over it
  // The smoothed rate on an even grid (for plots): rate[i] at rateT0 + i rateDt.
  double rateT0 = 0.0, rateDt = 0.0;
  std::vector<double> rate;
};

Phases segmentPhases(std::span<const double> time, std::span<const double> psi, const PhaseDef& def = {});

}  // namespace hemiroll::analysis
