#include "engine/analysis/RoseDetector.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "engine/analysis/CircleFit.h"
#include "engine/analysis/DominantTone.h"
#include "engine/analysis/Extrema.h"
#include "engine/analysis/Filters.h"
#include "engine/analysis/Wording.h"

namespace hemiroll::analysis {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double at(const std::vector<double>& v, double position) {
  const auto i = static_cast<std::size_t>(std::clamp(std::floor(position), 0.0, static_cast<double>(v.size() - 1)));
  const std::size_t j = std::min(i + 1, v.size() - 1);
  const double w = std::clamp(position - static_cast<double>(i), 0.0, 1.0);
  return v[i] * (1.0 - w) + v[j] * w;
}

struct Leaf {
  double start = 0.0, end = 0.0;  // fractional sample positions of the two minima
  double tip = 0.0;               // fractional sample position of the maximum
  double angle = 0.0;             // [rad] advance about the centre, signed
  double outer = 0.0, inner = 0.0;
};

// The distances from the centre, and what the angles about it need: the
// angle of point i, unwrapped, is atan2 about the centre + offset[i]
// (unwrapAngles' bits), taken only where a leaf ends (issue 32: an atan2
// per sample had been 2-3 % of a sweep point's analysis).
struct Path {
  std::vector<double> rho, offset;
  const std::vector<double>* x = nullptr;
  const std::vector<double>* y = nullptr;
  double cx = 0.0, cy = 0.0;
  double theta(std::size_t i) const {
    const double a = std::atan2((*y)[i] - cy, (*x)[i] - cx);
    return i == 0 ? a : a + offset[i];  // unwrapAngles leaves the first as it is
  }
  // At a fractional sample position, as `at` interpolates a column.
  double thetaAt(double position) const {
    const auto i = static_cast<std::size_t>(std::clamp(std::floor(position), 0.0, static_cast<double>(rho.size() - 1)));
    const std::size_t j = std::min(i + 1, rho.size() - 1);
    const double w = std::clamp(position - static_cast<double>(i), 0.0, 1.0);
    return theta(i) * (1.0 - w) + theta(j) * w;
  }
};

// The distance from (cx, cy); the angle about it only where asked: the
// centre's search needs the distances alone, and the angles' atan2 were
// most of its cost (issue 32).
Path about(const std::vector<double>& x, const std::vector<double>& y, double cx, double cy) {
  Path p{std::vector<double>(x.size()), {}};
  for (std::size_t i = 0; i < x.size(); ++i) p.rho[i] = std::hypot(x[i] - cx, y[i] - cy);
  return p;
}
void addAngles(Path& p, const std::vector<double>& x, const std::vector<double>& y, double cx, double cy) {
  p.offset = unwrapOffsetsAbout(x, y, cx, cy);
  p.x = &x, p.y = &y, p.cx = cx, p.cy = cy;
}

double rhoDelta(const std::vector<double>& rho, double fraction) {
  constexpr double kPercentiles[] = {0.05, 0.95};
  const std::vector<double> p = quantiles(rho, kPercentiles);
  return fraction * (p[1] - p[0]);
}

std::vector<Leaf> leavesOf(const Path& p, const std::vector<Extremum>& ex) {
  std::vector<Leaf> leaves;
  for (std::size_t i = 0; i + 2 < ex.size(); ++i) {
    if (ex[i].isMaximum) continue;
    const Extremum &a = ex[i], &tip = ex[i + 1], &b = ex[i + 2];
    leaves.push_back({a.position, b.position, tip.position, p.thetaAt(b.position) - p.thetaAt(a.position),
                      tip.value, 0.5 * (a.value + b.value)});
  }
  return leaves;
}

// The longest run of leaves with the dominant sense whose angle and duration
// lie within `tolerance` of the run's own medians (a fixed point from the
// medians of all such leaves).
std::pair<std::size_t, std::size_t> regularRun(const std::vector<Leaf>& leaves, int sense, double tolerance) {
  std::vector<bool> candidate(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i) candidate[i] = leaves[i].angle * sense > 0.0;
  std::size_t first = 0, last = leaves.size();  // [first, last)
  for (int iteration = 0; iteration < 10; ++iteration) {
    std::vector<double> angles, durations;
    for (std::size_t i = first; i < last; ++i)
      if (candidate[i]) angles.push_back(std::abs(leaves[i].angle)), durations.push_back(leaves[i].end - leaves[i].start);
    if (angles.empty()) return {0, 0};
    const double mAngle = median(angles), mDuration = median(durations);
    std::size_t bestFirst = 0, bestLast = 0, runFirst = 0;
    for (std::size_t i = 0; i <= leaves.size(); ++i) {
      const bool ok = i < leaves.size() && candidate[i] &&
                      std::abs(std::abs(leaves[i].angle) - mAngle) <= tolerance * mAngle &&
                      std::abs(leaves[i].end - leaves[i].start - mDuration) <= tolerance * mDuration;
      if (!ok) {
        if (i - runFirst > bestLast - bestFirst) bestFirst = runFirst, bestLast = i;
        runFirst = i + 1;
      }
    }
    if (bestFirst == first && bestLast == last) break;
    first = bestFirst, last = bestLast;
  }
  return {first, last};
}

// The centre the leaves turn about: the bounding box's, then (up to three
// times) the centre of the circle through the leaf tips, while that stays
// inside the box. Returns the path about it; (cx, cy) is the centre.
Path centredPath(const std::vector<double>& sx, const std::vector<double>& sy, double xMin, double xMax, double yMin,
                 double yMax, double hysteresis, double& cx, double& cy) {
  cx = 0.5 * (xMin + xMax), cy = 0.5 * (yMin + yMax);
  Path path = about(sx, sy, cx, cy);
  for (int iteration = 0; iteration < 3; ++iteration) {
    std::vector<double> tx, ty;
    for (const Extremum& e : findExtrema(path.rho, rhoDelta(path.rho, hysteresis)))
      if (e.isMaximum) tx.push_back(at(sx, e.position)), ty.push_back(at(sy, e.position));
    const CircleFit tips = fitCircle(tx, ty);
    if (tx.size() < 3 || !tips.ok || !(tips.curvature > 0.0)) break;
    if (tips.centreX < xMin || tips.centreX > xMax || tips.centreY < yMin || tips.centreY > yMax) break;
    cx = tips.centreX, cy = tips.centreY;
    path = about(sx, sy, cx, cy);
  }
  addAngles(path, sx, sy, cx, cy);
  return path;
}

// The run's leaves [first, last) measured: per revolution, radii, periods,
// tips. Returns the angle the run sweeps about the centre [rad].
double measureRun(const std::vector<Leaf>& leaves, std::size_t first, std::size_t last, double dt,
                  const std::vector<double>& sx, const std::vector<double>& sy, RoseFeatures& out,
                  std::vector<double>& outer, std::vector<double>& inner, std::vector<double>& radius,
                  std::vector<double>& period) {
  std::vector<double> perLeaf;
  double runAngle = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    const Leaf& l = leaves[i];
    runAngle += std::abs(l.angle);
    perLeaf.push_back(kTwoPi / std::abs(l.angle));
    outer.push_back(l.outer), inner.push_back(l.inner), radius.push_back(0.5 * (l.outer - l.inner));
    period.push_back((l.end - l.start) * dt);
    out.tipX.push_back(at(sx, l.tip)), out.tipY.push_back(at(sy, l.tip));
  }
  out.leavesPerCycle = kTwoPi * static_cast<double>(out.leafCount) / runAngle;
  out.leavesPerCycleSpread = standardDeviation(perLeaf);
  out.cycles = runAngle / kTwoPi;
  return runAngle;
}

// Leaves per complete revolution: each leaf belongs to the revolution its
// middle lies in; a revolution counts when the run covers it to within half
// a leaf. Then the confidence: equal leaves over a full revolution are 1.
void countRevolutions(const std::vector<Leaf>& leaves, std::size_t first, std::size_t last, double runAngle,
                      RoseFeatures& out) {
  const double halfLeaf = 0.5 * runAngle / static_cast<double>(out.leafCount);
  const auto complete = static_cast<std::size_t>(std::floor((runAngle + halfLeaf) / kTwoPi));
  out.leavesPerClosedCycle.assign(complete, 0);
  double swept = 0.0;
  for (std::size_t i = first; i < last; ++i) {
    const auto cycle = static_cast<std::size_t>(std::floor((swept + 0.5 * std::abs(leaves[i].angle)) / kTwoPi));
    if (cycle < complete) ++out.leavesPerClosedCycle[cycle];
    swept += std::abs(leaves[i].angle);
  }
  std::vector<double> angles;
  for (std::size_t i = first; i < last; ++i) angles.push_back(std::abs(leaves[i].angle));
  const double cv = standardDeviation(angles) / mean(angles);
  out.confidence = std::clamp(1.0 - cv, 0.0, 1.0) * std::min(1.0, out.cycles);
}

}  // namespace

RoseFeatures detectRose(std::span<const double> time, std::span<const double> x, std::span<const double> y,
                        const RoseDef& def) {
  const std::span<const double> channels[] = {x, y};
  return detectRose(resampleUniform(time, channels, def.sampling), def);
}

// Smooth, find the centre, check that the distance from it is modulated
// with one clear period, cut the path into leaves, keep the longest regular
// run, measure it.
RoseFeatures detectRose(const UniformSeries& series, const RoseDef& def) {
  RoseFeatures out;
  if (!series.ok()) {
    out.reason = "no rose: " + series.problem;
    return out;
  }
  const std::size_t h = halfWidthFor(def.smoothingTime, series.dt);
  const auto [sx, sy] = movingAverages(series.channels[0], series.channels[1], h);
  const auto [xMin, xMax] = std::minmax_element(sx.begin(), sx.end());
  const auto [yMin, yMax] = std::minmax_element(sy.begin(), sy.end());
  if (std::hypot(*xMax - *xMin, *yMax - *yMin) < 1e-6) {
    out.reason = "no rose: the point does not move (extent below 1 um)";
    return out;
  }
  double cx = 0.0, cy = 0.0;
  const Path path = centredPath(sx, sy, *xMin, *xMax, *yMin, *yMax, def.hysteresis, cx, cy);
  out.centreX = cx, out.centreY = cy;

  constexpr double kLevels[] = {0.05, 0.5, 0.95};
  const std::vector<double> levels = quantiles(path.rho, kLevels);
  const double rhoMedian = levels[1];
  const double rhoRange = levels[2] - levels[0];  // rhoDelta's, taken once
  const double modulation = rhoRange / rhoMedian;
  if (!(modulation >= def.minModulation)) {
    out.reason = "no rose: the distance from the centre varies by only " + shortNumber(100.0 * modulation) +
                 " % (a circle or a still point has no leaves; needs " + shortNumber(100.0 * def.minModulation) + " %)";
    return out;
  }
  std::vector<std::complex<double>> rhoSignal(path.rho.begin(), path.rho.end());
  const Tone tone = dominantTone(rhoSignal, series.dt,
                                 {.minFrequency = 3.0 / series.duration(), .maxFrequency = def.maxLeafFrequency,
                                  .bothSigns = false});
  out.toneShare = tone.share;
  if (!tone.found || tone.share < def.minShare) {
    out.reason = "no rose: the distance from the centre has no clear period (its strongest tone holds " +
                 shortNumber(100.0 * tone.share) + " % of its variation, needs " + shortNumber(100.0 * def.minShare) + " %)";
    return out;
  }

  const std::vector<Leaf> leaves = leavesOf(path, findExtrema(path.rho, def.hysteresis * rhoRange));
  double total = 0.0;
  for (const Leaf& l : leaves) total += l.angle;
  out.sense = total >= 0.0 ? 1 : -1;
  const auto [first, last] = regularRun(leaves, out.sense, def.regularity);
  out.leafCount = static_cast<int>(last - first);
  if (out.leafCount < def.minLeaves) {
    out.reason = "no rose: only " + std::to_string(out.leafCount) + " regular leaves in a row (of " +
                 std::to_string(leaves.size()) + " found; needs " + std::to_string(def.minLeaves) + ")";
    return out;
  }

  std::vector<double> outer, inner, radius, period;
  const double runAngle = measureRun(leaves, first, last, series.dt, sx, sy, out, outer, inner, radius, period);
  if (out.leavesPerCycle < def.minLeavesPerCycle) {
    out.reason = "no rose: the leaves do not go round the centre (" + shortNumber(out.leavesPerCycle) +
                 " leaves per revolution, needs " + shortNumber(def.minLeavesPerCycle) + ")";
    return out;
  }
  out.found = true;
  out.leaves = static_cast<int>(std::lround(out.leavesPerCycle));
  out.leafRadius = summarize(radius);
  out.outerRadius = summarize(outer);
  out.innerRadius = summarize(inner);
  out.leafPeriod = summarize(period);
  out.span = {series.time(0) + leaves[first].start * series.dt, series.time(0) + leaves[last - 1].end * series.dt};
  countRevolutions(leaves, first, last, runAngle, out);
  return out;
}

}  // namespace hemiroll::analysis
