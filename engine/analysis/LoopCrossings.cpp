#include "engine/analysis/LoopCrossings.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>

namespace hemiroll::analysis {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * kPi;

// Inlined into the loops below so that they need no call per sample.
[[gnu::always_inline]] inline double cheapAtan2Inline(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const bool steep = ay > ax;
  const double t = steep ? ax / ay : ay / ax;  // in [0, 1]
  const double t2 = t * t;
  double r = t * (0.9998660 + t2 * (-0.3302995 + t2 * (0.1801410 + t2 * (-0.0851330 + t2 * 0.0208351))));
  if (steep) r = 0.5 * kPi - r;
  if (std::signbit(x)) r = kPi - r;
  return std::signbit(y) ? -r : r;
}

// The multiple of 2 pi that unwrapAngles takes off for a step (under 3 rad
// it skips the rounding, whose answer is 0 there).
double turnOf(double step) { return std::abs(step) < 3.0 ? 0.0 : std::round(step / kTwoPi); }

// Whether a step's turn is the same as that of every step within `margin`
// of it: it lies farther than that from the nearest odd multiple of pi, the
// boundaries of turnOf. False for NaN.
bool turnIsClear(double step, double margin) {
  if (std::abs(step) < 3.0 - margin) return true;
  const double q = step / kTwoPi;
  return std::abs(q - std::floor(q) - 0.5) * kTwoPi > margin;
}

// unwrapAngles' offsets (what it adds to each angle: 0 for the first) for
// angles whose approximations `approx` make each step within `margin` of the
// exact one; exact(i) is angle i, asked only where a step's turn is not clear.
template <class Exact>
std::vector<double> unwrapOffsets(const std::vector<double>& approx, double margin, Exact exact) {
  std::vector<double> offsets(approx.size(), 0.0);
  double offset = 0.0;
  for (std::size_t i = 1; i < approx.size(); ++i) {
    const double step = approx[i] - approx[i - 1];
    const double turn = turnIsClear(step, margin) ? turnOf(step) : turnOf(exact(i) - exact(i - 1));
    // Subtracting 2 pi x (+-0) leaves the offset as it is (it is never -0).
    if (turn != 0.0) offset -= kTwoPi * turn;
    offsets[i] = offset;
  }
  return offsets;
}

double largestMagnitude(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));  // NaN is skipped: then the margins below are NaN anyway
  return m;
}

// A rounding's error bound for values of magnitude up to `magnitude` (and a
// few pi), generously: each value below goes through at most five roundings.
double roundingSlack(double magnitude) { return 64.0 * DBL_EPSILON * (magnitude + 8.0); }

}  // namespace

double cheapAtan2(double y, double x) { return cheapAtan2Inline(y, x); }

std::vector<double> loopCrossings(std::span<const double> tx, std::span<const double> ty,
                                  std::span<const double> vx, std::span<const double> vy, std::size_t lag,
                                  int sense) {
  const std::size_t n = std::min(vx.size(), vy.size()), m = std::min(tx.size(), ty.size());
  std::vector<double> positions;
  if (n == 0 || m == 0) return positions;
  auto travelAngle = [&](std::size_t i) { return std::atan2(vy[i], vx[i]); };
  auto tangentAngle = [&](std::size_t k) { return std::atan2(ty[k], tx[k]); };
  auto tangentAt = [&](std::size_t i) { return std::min(i < lag ? 0 : i - lag, m - 1); };

  // The headings, unwrapped: the exact construction's offsets, from cheap angles.
  std::vector<double> travel(n), tangent(m);
  for (std::size_t i = 0; i < n; ++i) travel[i] = cheapAtan2Inline(vy[i], vx[i]);
  for (std::size_t k = 0; k < m; ++k) tangent[k] = cheapAtan2Inline(ty[k], tx[k]);
  const double headingMargin = 2.0 * kCheapAtan2Error + roundingSlack(0.0);
  const std::vector<double> travelOffset = unwrapOffsets(travel, headingMargin, travelAngle);
  const std::vector<double> tangentOffset = unwrapOffsets(tangent, headingMargin, tangentAngle);
  // unwrapAngles leaves the first angle as it is and adds the offset to the others.
  auto unwrapped = [](double angle, const std::vector<double>& offsets, std::size_t i) {
    return i == 0 ? angle : angle + offsets[i];
  };
  auto exactRaw = [&](std::size_t i) {
    const std::size_t k = tangentAt(i);
    return unwrapped(travelAngle(i), travelOffset, i) - unwrapped(tangentAngle(k), tangentOffset, k);
  };

  // The relative direction before its own unwrapping; each within twice the
  // cheap error (and roundings) of the exact one.
  std::vector<double> raw(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = tangentAt(i);
    raw[i] = unwrapped(travel[i], travelOffset, i) - unwrapped(tangent[k], tangentOffset, k);
  }
  const double offsetsMagnitude = largestMagnitude(travelOffset) + largestMagnitude(tangentOffset);
  const double rawMargin = 4.0 * kCheapAtan2Error + roundingSlack(offsetsMagnitude);
  const std::vector<double> relativeOffset = unwrapOffsets(raw, rawMargin, exactRaw);

  // HelixDetector's shift to (-pi, pi] and first target, from the exact front.
  const double front = exactRaw(0);
  const double shift = -2.0 * kPi * std::round(front / (2.0 * kPi));
  const double frontShifted = front + shift;
  auto exactRelative = [&](std::size_t i) { return unwrapped(exactRaw(i), relativeOffset, i) + shift; };
  const double s = sense;
  double target = s * kPi * (2.0 * std::floor((s * frontShifted / kPi + 1.0) / 2.0) + 1.0);
  const double crossMargin =
      2.0 * kCheapAtan2Error + roundingSlack(offsetsMagnitude + largestMagnitude(relativeOffset) + std::abs(shift));
  double previous = frontShifted;  // the exact relative direction at i - 1, where known
  bool previousKnown = true;
  for (std::size_t i = 1; i < n; ++i) {
    const double approx = unwrapped(raw[i], relativeOffset, i) + shift;
    const double gap = approx - target;
    double exact = 0.0;
    bool exactKnown = false;
    if (std::abs(gap) > crossMargin + roundingSlack(std::abs(target))) {
      if (s * gap < 0.0) {
        previousKnown = false;
        continue;
      }
    } else {
      exact = exactRelative(i), exactKnown = true;
      if (s * (exact - target) < 0.0) {
        previous = exact, previousKnown = true;
        continue;
      }
    }
    if (!exactKnown) exact = exactRelative(i);
    if (!previousKnown) previous = exactRelative(i - 1);
    const double w = (target - previous) / (exact - previous);
    positions.push_back(static_cast<double>(i - 1) + std::clamp(w, 0.0, 1.0));
    target += s * 2.0 * kPi;
    previous = exact, previousKnown = true;
  }
  return positions;
}

}  // namespace hemiroll::analysis
