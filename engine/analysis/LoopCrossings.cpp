#include "engine/analysis/LoopCrossings.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <numbers>

#include "engine/analysis/CpuLanes.h"

namespace hemiroll::analysis {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * kPi;

// Branch-free (the quarter changes every quarter loop, a branch there is
// mispredicted), so that the lanes below can run it side by side: the same
// operations in every lane, lanes of one double included.
template <std::size_t W>
[[gnu::always_inline]] inline void cheapAtan2At(const double* y, const double* x, double* out) {
  typedef double V __attribute__((vector_size(W * sizeof(double))));
  typedef long long Mask __attribute__((vector_size(W * sizeof(long long))));
  V vy, vx;
  std::memcpy(&vy, y, sizeof vy);
  std::memcpy(&vx, x, sizeof vx);
  const V ax = vx < 0.0 ? -vx : vx, ay = vy < 0.0 ? -vy : vy;
  const Mask steep = ay > ax;
  const V t = (steep ? ax : ay) / (steep ? ay : ax);  // in [0, 1]
  const V t2 = t * t;
  V r = t * (0.9998660 + t2 * (-0.3302995 + t2 * (0.1801410 + t2 * (-0.0851330 + t2 * 0.0208351))));
  r = steep ? 0.5 * kPi - r : r;
  const Mask signX = (Mask)vx < 0, signY = (Mask)vy < 0;  // a vector cast: the bits
  r = signX ? kPi - r : r;
  r = signY ? -r : r;  // r >= 0 (or NaN) before: y's sign, as atan2's
  std::memcpy(out, &r, sizeof r);
}

[[gnu::always_inline]] inline double cheapAtan2Scalar(double y, double x) {
  double r;
  cheapAtan2At<1>(&y, &x, &r);
  return r;
}

// Each direction's cheap angle, W lanes at a time (one copy per instruction
// set, chosen once by the CPU as Filters' sums are).
template <std::size_t W>
[[gnu::always_inline]] inline void cheapAtan2s(const double* y, const double* x, std::size_t n, double* out) {
  std::size_t i = 0;
  for (; i + W <= n; i += W) {
    cheapAtan2At<W>(y + i, x + i, out + i);
  }
  for (; i < n; ++i) out[i] = cheapAtan2Scalar(y[i], x[i]);
}
__attribute__((target("avx512f"))) void cheapAtan2s8(const double* y, const double* x, std::size_t n, double* out) {
  cheapAtan2s<8>(y, x, n, out);
}
__attribute__((target("avx2"))) void cheapAtan2s4(const double* y, const double* x, std::size_t n, double* out) {
  cheapAtan2s<4>(y, x, n, out);
}
void cheapAtan2s2(const double* y, const double* x, std::size_t n, double* out) { cheapAtan2s<2>(y, x, n, out); }

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
struct Offsets {
  std::vector<double> at;
  double largest = 0.0;  // the largest magnitude among them (NaN if one is)
};
template <class Exact>
Offsets unwrapOffsets(const std::vector<double>& approx, double margin, Exact exact) {
  Offsets offsets{std::vector<double>(approx.size(), 0.0)};
  double offset = 0.0;
  for (std::size_t i = 1; i < approx.size(); ++i) {
    const double step = approx[i] - approx[i - 1];
    const double turn = turnIsClear(step, margin) ? turnOf(step) : turnOf(exact(i) - exact(i - 1));
    // Subtracting 2 pi x (+-0) leaves the offset as it is (it is never -0).
    if (turn != 0.0) {
      offset -= kTwoPi * turn;
      offsets.largest = std::isnan(offset) ? offset : std::max(offsets.largest, std::abs(offset));
    }
    offsets.at[i] = offset;
  }
  return offsets;
}

// A rounding's error bound for values of magnitude up to `magnitude` (and a
// few pi), generously: each value below goes through at most five roundings.
double roundingSlack(double magnitude) { return 64.0 * DBL_EPSILON * (magnitude + 8.0); }

}  // namespace

double cheapAtan2(double y, double x) { return cheapAtan2Scalar(y, x); }

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
  static const auto cheapAtan2s = copyForThisCpu(&cheapAtan2s8, &cheapAtan2s4, &cheapAtan2s2);
  cheapAtan2s(vy.data(), vx.data(), n, travel.data());
  cheapAtan2s(ty.data(), tx.data(), m, tangent.data());
  const double headingMargin = 2.0 * kCheapAtan2Error + roundingSlack(0.0);
  const Offsets travelOffset = unwrapOffsets(travel, headingMargin, travelAngle);
  const Offsets tangentOffset = unwrapOffsets(tangent, headingMargin, tangentAngle);
  // unwrapAngles leaves the first angle as it is and adds the offset to the others.
  auto unwrapped = [](double angle, const Offsets& offsets, std::size_t i) {
    return i == 0 ? angle : angle + offsets.at[i];
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
  const double offsetsMagnitude = travelOffset.largest + tangentOffset.largest;
  const double rawMargin = 4.0 * kCheapAtan2Error + roundingSlack(offsetsMagnitude);
  const Offsets relativeOffset = unwrapOffsets(raw, rawMargin, exactRaw);

  // HelixDetector's shift to (-pi, pi] and first target, from the exact front.
  const double front = exactRaw(0);
  const double shift = -2.0 * kPi * std::round(front / (2.0 * kPi));
  const double frontShifted = front + shift;
  auto exactRelative = [&](std::size_t i) { return unwrapped(exactRaw(i), relativeOffset, i) + shift; };
  const double s = sense;
  double target = s * kPi * (2.0 * std::floor((s * frontShifted / kPi + 1.0) / 2.0) + 1.0);
  const double crossMargin =
      2.0 * kCheapAtan2Error + roundingSlack(offsetsMagnitude + relativeOffset.largest + std::abs(shift));
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
