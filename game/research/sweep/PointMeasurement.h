#pragma once
// One sweep point: run the 8-state rose drive headless from the point's
// start, sample it at 100 Hz, and measure what docs/SWEEP.md defines:
// the domain event and when, the largest tilt, the mean precession rate, the
// steady precession phase and its rate's spread, the arc of the contact
// trace with its error, the drift along it, the loops, the leaves, and
// whether all of the paper's features hold together ("paper-like").
// Deterministic: the same point on the same binary gives the same bits,
// whatever thread runs it (no shared state; engine/analysis is pure).

#include <string>
#include <vector>

#include "engine/analysis/TrialAnalyzer.h"
#include "engine/physics/DomainEvents.h"
#include "game/research/sweep/SweepGrid.h"

namespace hemiroll::game {

struct PointMeasurement {
  physics::DomainEvent event = physics::DomainEvent::None;
  double eventTime = 0.0;       // [s] when event != None
  double simulated = 0.0;       // [s] time simulated (the duration unless an event stopped the run)
  double duration = 0.0;        // [s] the spec's duration (the denominator of steadyFraction)
  double maxTilt = 0.0;         // [rad] largest tilt of the face normal from vertical over the samples
  double meanRate = 0.0;        // [rad/s] (psi(end) - psi(0)) / simulated; 0 when nothing was simulated
  analysis::TrialFeatures features;
  bool helixInSteadyPhase = false;  // the arc and loops were measured in the steady phase (else the whole run)
  bool paperLike = false;           // every feature of the paper's run together (paperLike())

  double steadyFraction() const;    // steady phase duration / duration; 0 without one
  double relativeSpread() const;    // steady rate spread / |median|; 0 without a steady phase
  // No event; a steady phase covering at least minSteadyFraction of the
  // run with a relative spread at most maxRelativeSpread; the arc and the
  // loops found in that phase.
  bool meetsPaper(const task::SweepAnalysisDef& def) const;
  // What was not found, and why, in one line ("" when everything was).
  std::string notes() const;
};

// A lower bound of cos(u) cos(v), the cosine of the face normal's tilt from
// vertical, from a few multiplications: within 1e-6 of it for |u|, |v| up to
// 0.6 rad; -1, below every cosine, where it does not bound (an angle beyond
// ~1.57 rad, or NaN).
double cosTiltLowerBound(double u, double v);

// Rows every round(0.01 s / dt) steps (at least every step): the analysis
// resamples to at most 100 Hz anyway.
long long sampleEvery(double timeStep);

PointMeasurement measurePoint(const SweepGrid& grid, const SweepPoint& point);

// The same measurements for several points, the same bits: with laneWidth > 1
// (a width this CPU runs) and points the lockstep run takes (the rose drive
// with rk4), their trajectories are integrated together in SIMD lanes
// (RoseLockstepRun); otherwise one after the other.
std::vector<PointMeasurement> measurePoints(const SweepGrid& grid, const std::vector<SweepPoint>& points,
                                            int laneWidth);

}  // namespace hemiroll::game
