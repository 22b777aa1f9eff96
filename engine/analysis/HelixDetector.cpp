#include "engine/analysis/HelixDetector.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "engine/analysis/CircleFit.h"
#include "engine/analysis/DominantTone.h"
#include "engine/analysis/Filters.h"
#include "engine/analysis/LoopCrossings.h"
#include "engine/analysis/Wording.h"

namespace hemiroll::analysis {

namespace {

constexpr double kPi = std::numbers::pi;

// The arc through the low-passed trace lx, ly (already cut to full windows).
void measureArc(const std::vector<double>& lx, const std::vector<double>& ly, double dt, double period,
                ArcFeatures& arc) {
  const std::size_t n = lx.size();
  // Kept whole: the loops are placed along it (findLoops).
  arc.along.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) arc.along[i] = arc.along[i - 1] + std::hypot(lx[i] - lx[i - 1], ly[i] - ly[i - 1]);
  arc.length = n > 0 ? arc.along.back() : 0.0;
  const double duration = dt * static_cast<double>(n - 1);
  arc.driftSpeed = arc.length / duration;
  const CircleFit fit = fitCircle(lx, ly);
  if (!fit.ok) {
    arc.reason = "no arc: the low-passed trace does not move";
    return;
  }
  arc.rmsResidual = fit.rmsResidual;
  if (fit.curvature > 0.0) {
    double turn = 0.0;  // > 0: the trace goes counter-clockwise about the centre
    for (std::size_t i = 1; i < n; ++i)
      turn += (lx[i] - lx[i - 1]) * (fit.centreY - ly[i - 1]) - (ly[i] - ly[i - 1]) * (fit.centreX - lx[i - 1]);
    arc.curvature = turn >= 0.0 ? fit.curvature : -fit.curvature;
    arc.radius = fit.radius;
    arc.centreX = fit.centreX, arc.centreY = fit.centreY;
    arc.sweptAngle = sweptAngleAbout(lx, ly, fit.centreX, fit.centreY);
  }
  const double independent = duration / period;
  arc.curvatureError = arc.length > 0.0 ? fit.rmsResidual / (arc.length * arc.length) *
                                              std::sqrt(720.0 / (independent + 4.0))
                                        : 0.0;
  const double sagitta = arc.length * arc.length * std::abs(arc.curvature) / 8.0;
  if (!(std::abs(arc.curvature) > 3.0 * arc.curvatureError)) {
    arc.reason = "not curved: the trace is straight within its scatter (curvature " + shortNumber(arc.curvature) +
                 " 1/m, standard error " + shortNumber(arc.curvatureError) + " 1/m)";
  } else if (!(fit.rmsResidual < 0.5 * sagitta)) {
    arc.reason = "not an arc: the trace strays " + shortNumber(fit.rmsResidual) + " m (rms) from the best circle, more than " +
                 "half its bend (" + shortNumber(sagitta) + " m)";
  } else {
    arc.found = true;
  }
}

// The arc: a moving average over one loop period (an odd number of samples,
// 2 h + 1, nearest to it), without the ends where the window is not full.
void lowPassArc(const UniformSeries& s, double period, std::size_t h, ArcFeatures& arc) {
  if (s.size() < 2 * h + 8) {
    arc.reason = "no arc: " + shortNumber(s.duration()) + " s is too short for the low-pass window of " + shortNumber(period) + " s";
    return;
  }
  const auto [ax, ay] = movingAverages(s.channels[0], s.channels[1], h);
  arc.x.assign(ax.begin() + static_cast<std::ptrdiff_t>(h), ax.end() - static_cast<std::ptrdiff_t>(h));
  arc.y.assign(ay.begin() + static_cast<std::ptrdiff_t>(h), ay.end() - static_cast<std::ptrdiff_t>(h));
  arc.span = {s.time(h), s.time(s.size() - 1 - h)};
  measureArc(arc.x, arc.y, s.dt, period, arc);
}

// A loop each time the direction of travel, relative to the arc's tangent
// (held constant over the cut ends), passes an odd multiple of pi in the
// loops' sense (loopCrossings): its time, place and distance along the arc;
// then the spacings between loops.
void findLoops(const ArcFeatures& arc, const std::vector<double>& vx, const std::vector<double>& vy,
               const UniformSeries& s, const std::vector<double>& sx, const std::vector<double>& sy, std::size_t h,
               LoopFeatures& loops) {
  const std::vector<double> tx = localSlope(arc.x, s.dt, 1), ty = localSlope(arc.y, s.dt, 1);
  const std::vector<double>& arcLength = arc.along;
  std::vector<double> along;
  for (const double position : loopCrossings(tx, ty, vx, vy, h, loops.sense)) {
    loops.times.push_back(s.t0 + position * s.dt);
    const auto j = static_cast<std::size_t>(position);
    loops.x.push_back(sx[j]), loops.y.push_back(sy[j]);
    const double k = std::clamp(position - static_cast<double>(h), 0.0, static_cast<double>(arcLength.size() - 1));
    along.push_back(arcLength[static_cast<std::size_t>(std::lround(k))]);
  }
  loops.count = static_cast<int>(loops.times.size());
  std::vector<double> dtLoops, dsLoops;
  for (std::size_t i = 1; i < loops.times.size(); ++i) {
    dtLoops.push_back(loops.times[i] - loops.times[i - 1]);
    dsLoops.push_back(along[i] - along[i - 1]);
  }
  loops.spacingTime = summarize(dtLoops);
  loops.spacingArc = summarize(dsLoops);
}

}  // namespace

HelixFeatures detectHelix(std::span<const double> time, std::span<const double> x, std::span<const double> y,
                          const HelixDef& def) {
  const std::span<const double> channels[] = {x, y};
  return detectHelix(resampleUniform(time, channels, def.sampling), def);
}

// Smooth, find the loops' period in the velocity, low-pass the trace over
// one period into the arc, then count the loops against the arc's tangent.
HelixFeatures detectHelix(const UniformSeries& s, const HelixDef& def) {
  HelixFeatures out;
  ArcFeatures& arc = out.arc;
  LoopFeatures& loops = out.loops;
  if (!s.ok()) {
    arc.reason = "no arc: " + s.problem;
    loops.reason = "no loops: " + s.problem;
    return out;
  }
  const std::size_t light = halfWidthFor(def.lightSmoothing, s.dt);
  const auto [sx, sy] = movingAverages(s.channels[0], s.channels[1], light);
  const std::vector<double> vx = localSlope(sx, s.dt, 1), vy = localSlope(sy, s.dt, 1);
  std::vector<std::complex<double>> velocity(vx.size());
  for (std::size_t i = 0; i < vx.size(); ++i) velocity[i] = {vx[i], vy[i]};
  const Tone tone = dominantTone(velocity, s.dt, {.minFrequency = 3.0 / s.duration(), .maxFrequency = def.maxLoopFrequency});
  loops.frequency = tone.frequency;
  loops.toneShare = tone.share;
  const bool periodic = tone.found && tone.share >= def.minShare;
  const double period = periodic ? 1.0 / std::abs(tone.frequency) : def.fallbackWindow;
  const auto h = static_cast<std::size_t>(std::max(0L, std::lround(0.5 * (period / s.dt - 1.0))));
  lowPassArc(s, period, h, arc);

  if (!periodic) {
    loops.reason = tone.found ? "no loops: the trace's velocity has no clear period (its strongest tone holds " +
                                    shortNumber(100.0 * tone.share) + " % of its variation, needs " +
                                    shortNumber(100.0 * def.minShare) + " %)"
                              : "no loops: the trace's velocity has no periodic part (it moves uniformly, turns "
                                "slowly or stands still)";
    return out;
  }
  if (arc.x.size() < 2) {
    loops.reason = "no loops: " + arc.reason.substr(arc.reason.find(':') + 2);
    return out;
  }
  loops.sense = tone.frequency >= 0.0 ? 1 : -1;
  findLoops(arc, vx, vy, s, sx, sy, h, loops);
  if (loops.count < def.minLoops) {
    loops.reason = "no loops: the direction of travel turns full circle only " + std::to_string(loops.count) +
                   " times (a wiggle, not a loop; needs " + std::to_string(def.minLoops) + ")";
    return out;
  }
  const double variation = loops.spacingTime.spread / loops.spacingTime.value;
  if (!(variation <= def.maxSpacingVariation)) {
    loops.reason = "no helix: " + std::to_string(loops.count) + " loops, but their spacing varies by " +
                   shortNumber(100.0 * variation) + " % (at most " + shortNumber(100.0 * def.maxSpacingVariation) + " %)";
    return out;
  }
  loops.found = true;
  return out;
}

}  // namespace hemiroll::analysis
