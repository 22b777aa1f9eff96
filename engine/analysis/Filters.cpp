#include "engine/analysis/Filters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <numbers>

#include "engine/analysis/CpuLanes.h"

namespace hemiroll::analysis {

std::size_t halfWidthFor(double duration, double dt) {
  if (!(duration > 0.0) || !(dt > 0.0)) return 0;
  return static_cast<std::size_t>(std::lround(0.5 * duration / dt));
}

namespace {

// The centred moving averages of C columns of equal length, their running
// sums side by side (so that none waits on the latency of its own chain of
// additions); each column's operations are one column's alone, so the same
// bits for any C. Prefix sums make every window O(1); the values are O(1)
// physical quantities, so the cancellation in the difference is harmless.
// Whole windows (i in [h, n - h)) divide two at a time as the sums reach
// them (issue 32: one division per value after the sums had been ~2/3 of
// the time); each lane's is the scalar division of its window.
template <std::size_t C>
std::array<std::vector<double>, C> movingAveragesOf(const std::array<std::span<const double>, C>& columns,
                                                    std::size_t halfWidth) {
  const std::size_t n = columns[0].size(), h = halfWidth;
  std::array<std::vector<double>, C> out;
  std::array<std::unique_ptr<double[]>, C> prefix;  // each written before it is read
  double run[C];
  for (std::size_t c = 0; c < C; ++c) out[c].resize(n), prefix[c].reset(new double[n + 1]), prefix[c][0] = run[c] = 0.0;
  std::size_t summed = 0;  // prefix[c][0 .. summed] are written; run[c] = prefix[c][summed]
  auto sumTo = [&](std::size_t last) {
    for (; summed < last; ++summed)
      for (std::size_t c = 0; c < C; ++c) prefix[c][summed + 1] = run[c] = run[c] + columns[c][summed];
  };
  const std::size_t wholeFirst = std::min(h, n), wholeLast = n > h && n - h > h ? n - h : wholeFirst;
  std::size_t i = wholeFirst;
  if (wholeLast > wholeFirst) {
    sumTo(wholeFirst + h);
    const auto width = static_cast<double>(2 * h + 1);
    for (; i + 2 <= wholeLast; i += 2) {
      for (std::size_t c = 0; c < C; ++c) {
        const double next = run[c] + columns[c][i + h], after = next + columns[c][i + h + 1];
        prefix[c][i + h + 1] = next, prefix[c][i + h + 2] = run[c] = after;
        storePair(&out[c][i], (DoublePair{next, after} - loadPair(&prefix[c][i - h])) / width);
      }
      summed = i + h + 2;
    }
  }
  sumTo(n);
  // The ends' shrinking windows, and a last whole one left over.
  auto one = [&](std::size_t j) {
    const std::size_t hj = std::min({h, j, n - 1 - j});
    const auto width = static_cast<double>(2 * hj + 1);
    for (std::size_t c = 0; c < C; ++c) out[c][j] = (prefix[c][j + hj + 1] - prefix[c][j - hj]) / width;
  };
  for (std::size_t j = 0; j < wholeFirst; ++j) one(j);
  for (std::size_t j = i; j < n; ++j) one(j);
  return out;
}

}  // namespace

std::vector<double> movingAverage(std::span<const double> values, std::size_t halfWidth) {
  return std::move(movingAveragesOf<1>({values}, halfWidth)[0]);
}

std::pair<std::vector<double>, std::vector<double>> movingAverages(std::span<const double> x,
                                                                   std::span<const double> y, std::size_t halfWidth) {
  if (x.size() != y.size()) return {movingAverage(x, halfWidth), movingAverage(y, halfWidth)};
  auto [outX, outY] = movingAveragesOf<2>({x, y}, halfWidth);
  return {std::move(outX), std::move(outY)};
}

namespace {

// The slopes of whole windows, num_i / scale with num_i = sum_k k (v[i+k] -
// v[i-k]) for k = 1 .. h in ascending k, for i in [first, last): groups of
// R vectors of W samples held in registers while k runs (issue 32: with the
// sums in memory, each k loaded and stored every sample's sum again, and
// the rate's 150-sample windows made this 12 % of a sweep point's analysis),
// divided there too (a pass dividing one value at a time had been most of
// a 3-sample window's cost). Each lane does the scalar operations of its
// sample in the scalar order (no contraction: -ffp-contract=off), so the
// slopes have the same bits at every width.
template <std::size_t W, std::size_t R>
[[gnu::always_inline]] inline void directWindowSlopes(const double* v, std::size_t first, std::size_t last,
                                                      std::size_t h, double scale, double* out) {
  typedef double Lanes __attribute__((vector_size(W * sizeof(double))));
  constexpr std::size_t kGroup = W * R;
  std::size_t i = first;
  for (; i + kGroup <= last; i += kGroup) {
    Lanes sum[R] = {};
    for (std::size_t k = 1; k <= h; ++k) {
      const double kk = static_cast<double>(k);
      for (std::size_t r = 0; r < R; ++r) {
        Lanes ahead, behind;
        std::memcpy(&ahead, v + i + r * W + k, sizeof ahead);
        std::memcpy(&behind, v + i + r * W - k, sizeof behind);
        sum[r] += kk * (ahead - behind);
      }
    }
    for (std::size_t r = 0; r < R; ++r) {
      const Lanes slope = sum[r] / scale;
      std::memcpy(out + i + r * W, &slope, sizeof slope);
    }
  }
  for (; i < last; ++i) {
    double sum = 0.0;
    for (std::size_t k = 1; k <= h; ++k) sum += static_cast<double>(k) * (v[i + k] - v[i - k]);
    out[i] = sum / scale;
  }
}

// The same slopes for long windows, with every load whole and aligned and
// three in four of them kept in registers from the step before (issue 32:
// the direct form's loads at v + i +- k mostly straddled two cache lines,
// two per vector and step, and bounded it). Each lane takes a stretch of
// `rows` samples, lane by lane side by side in a transposed copy whose row
// m holds each lane's sample m - h of its stretch; R consecutive rows advance
// together, and from step k to k + 1 their ahead rows move one row on and
// their behind rows one back, so each step loads one row of each. The last
// stretches overlap where the count is not a multiple of W R: a sample
// computed twice gets the same bits twice. The same operations per sample
// in the same order as the direct form, so the same bits.
template <std::size_t W>
[[gnu::always_inline]] inline void transposedWindowSlopes(const double* v, std::size_t first, std::size_t last,
                                                          std::size_t h, double scale, double* out) {
  typedef double Lanes __attribute__((vector_size(W * sizeof(double))));
  constexpr std::size_t R = 4;
  const std::size_t count = last - first;  // at least W R
  const std::size_t rows = ((count + W - 1) / W + R - 1) / R * R;
  std::size_t start[W];
  for (std::size_t j = 0; j < W; ++j) start[j] = first + std::min(j * rows, count - rows);
  const std::size_t height = rows + 2 * h;
  const std::unique_ptr<double[]> storage(new double[height * W + W]);
  double* const t = storage.get() + (W - reinterpret_cast<std::uintptr_t>(storage.get()) / sizeof(double) % W) % W;
  for (std::size_t m = 0; m < height; ++m)
    for (std::size_t j = 0; j < W; ++j) t[m * W + j] = v[start[j] - h + m];
  for (std::size_t o = 0; o < rows; o += R) {
    // Row o + r + h is sample o + r; ahead[r] and behind[r] are its rows
    // o + r + h + k and o + r + h - k at step k.
    Lanes sum[R] = {}, ahead[R], behind[R];
    for (std::size_t r = 0; r + 1 < R; ++r) {
      std::memcpy(&ahead[r], t + (o + h + 1 + r) * W, sizeof(Lanes));
      std::memcpy(&behind[r + 1], t + (o + h + r) * W, sizeof(Lanes));
    }
    for (std::size_t k = 1; k <= h; ++k) {
      std::memcpy(&ahead[R - 1], t + (o + h + k + R - 1) * W, sizeof(Lanes));
      std::memcpy(&behind[0], t + (o + h - k) * W, sizeof(Lanes));
      const double kk = static_cast<double>(k);
      for (std::size_t r = 0; r < R; ++r) sum[r] += kk * (ahead[r] - behind[r]);
      for (std::size_t r = 0; r + 1 < R; ++r) ahead[r] = ahead[r + 1], behind[R - 1 - r] = behind[R - 2 - r];
    }
    for (std::size_t r = 0; r < R; ++r) {
      double slope[W];
      const Lanes slopes = sum[r] / scale;
      std::memcpy(slope, &slopes, sizeof slopes);
      for (std::size_t j = 0; j < W; ++j) out[start[j] + o + r] = slope[j];
    }
  }
}

template <std::size_t W>
[[gnu::always_inline]] inline void wholeWindowSlopes(const double* v, std::size_t first, std::size_t last,
                                                     std::size_t h, double scale, double* out) {
  constexpr std::size_t R = 4;
  // Short windows: the copy would cost about what it saves.
  if (h >= 8 && last - first >= W * R) return transposedWindowSlopes<W>(v, first, last, h, scale, out);
  directWindowSlopes<W, R>(v, first, last, h, scale, out);
}

// One copy per instruction set, chosen once by the CPU (as BatchedRk4's
// lanes are): 8 lanes under AVX-512F, 4 under AVX2, SSE2's 2 otherwise.
__attribute__((target("avx512f"))) void wholeWindowSlopes8(const double* v, std::size_t first, std::size_t last,
                                                           std::size_t h, double scale, double* out) {
  wholeWindowSlopes<8>(v, first, last, h, scale, out);
}
__attribute__((target("avx2"))) void wholeWindowSlopes4(const double* v, std::size_t first, std::size_t last,
                                                        std::size_t h, double scale, double* out) {
  wholeWindowSlopes<4>(v, first, last, h, scale, out);
}
void wholeWindowSlopes2(const double* v, std::size_t first, std::size_t last, std::size_t h, double scale,
                        double* out) {
  wholeWindowSlopes<2>(v, first, last, h, scale, out);
}

}  // namespace

// Each sample's slope is sum_k k (v[i+k] - v[i-k]) / (sum_k 2 k^2 dt), k = 1
// .. h, both sums in ascending k. Where the window is whole (h = halfWidth)
// the samples' sums advance side by side in registers (wholeWindowSlopes) and
// the denominator is summed once; each sum still takes its terms in the same
// order, so the slopes have the same bits.
std::vector<double> localSlope(std::span<const double> values, double dt, std::size_t halfWidth) {
  const std::size_t n = values.size();
  std::vector<double> out(n, 0.0);
  if (n < 2) return out;
  halfWidth = std::max<std::size_t>(halfWidth, 1);
  // The denominators sum_k 2 k^2 for k = 1 .. h, each summed in ascending
  // k, so the one for h is the one for h - 1 plus 2 h^2: the same bits from
  // one running sum (the ends' shrinking windows need every h below halfWidth).
  const std::size_t widest = std::min(halfWidth, n);  // no window is wider than the samples
  std::vector<double> denominators(widest + 1, 0.0);
  for (std::size_t k = 1; k <= widest; ++k) {
    const double kk = static_cast<double>(k);
    denominators[k] = denominators[k - 1] + 2.0 * kk * kk;
  }
  auto windowSlope = [&](std::size_t i, std::size_t h) {
    double num = 0.0;
    for (std::size_t k = 1; k <= h; ++k) num += static_cast<double>(k) * (values[i + k] - values[i - k]);
    return num / (denominators[h] * dt);
  };
  // Whole windows: i in [halfWidth, n - halfWidth).
  const std::size_t first = std::min(halfWidth, n), last = n > halfWidth ? std::max(first, n - halfWidth) : first;
  if (last > first) {
    static const auto slopes = copyForThisCpu(&wholeWindowSlopes8, &wholeWindowSlopes4, &wholeWindowSlopes2);
    slopes(values.data(), first, last, halfWidth, denominators[halfWidth] * dt, out.data());
  }
  // The ends' shrinking windows: sample i and its mirror n - 1 - i have the
  // same width, so their sums run side by side (each in its own order).
  std::vector<bool> done(n, false);
  for (std::size_t i = 1; i < first; ++i) {
    const std::size_t j = n - 1 - i, h = std::min({halfWidth, i, j});
    if (j < last || j <= i || h == 0) continue;
    double numI = 0.0, numJ = 0.0;
    for (std::size_t k = 1; k <= h; ++k) {
      const double kk = static_cast<double>(k);
      numI += kk * (values[i + k] - values[i - k]);
      numJ += kk * (values[j + k] - values[j - k]);
    }
    out[i] = numI / (denominators[h] * dt);
    out[j] = numJ / (denominators[h] * dt);
    done[i] = done[j] = true;
  }
  // The rest of the ends, one at a time.
  auto end = [&](std::size_t i) {
    if (done[i]) return;
    const std::size_t h = std::min({halfWidth, i, n - 1 - i});
    // An end sample: the one-sided difference to its neighbour.
    if (h == 0) out[i] = i == 0 ? (values[1] - values[0]) / dt : (values[n - 1] - values[n - 2]) / dt;
    else out[i] = windowSlope(i, h);
  };
  for (std::size_t i = 0; i < first; ++i) end(i);
  for (std::size_t i = last; i < n; ++i) end(i);
  return out;
}

std::vector<double> unwrapAngles(std::span<const double> angles) {
  std::vector<double> out(angles.begin(), angles.end());
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double offset = 0.0;
  for (std::size_t i = 1; i < out.size(); ++i) {
    const double step = angles[i] - angles[i - 1];
    // A step under 3 rad rounds to no turn; skipping its division and
    // rounding leaves the offset as it was (it is never -0, so subtracting
    // +-0 changes no bit).
    if (!(std::abs(step) < 3.0)) offset -= kTwoPi * std::round(step / kTwoPi);
    out[i] = angles[i] + offset;
  }
  return out;
}

namespace {

// Which quarter about the centre a point lies in strictly inside: 0 about
// +x, 1 about +y, 2 about -y, 3 and 4 the halves of the one about -x above
// and below the axis; 5 on a diagonal, on the -x axis, at the centre or not
// finite. Two points strictly inside one of the first five have atan2 at
// most pi / 2 apart (plus rounding): a step that unwrapAngles rounds to no
// turn. Across the -x axis the angle wraps from pi to -pi (and there,
// atan2(+-0, x < 0) is +-pi, atan2(0, -0) = pi): hence the two halves
// (issue 32: with the whole quarter about -x asked, a quarter of a rose's
// points took an atan2 each).
int quarterOf(double dx, double dy) {
  if (dx > std::abs(dy)) return 0;
  if (dy > std::abs(dx)) return 1;
  if (-dy > std::abs(dx)) return 2;
  if (-dx > std::abs(dy)) return dy > 0.0 ? 3 : dy < 0.0 ? 4 : 5;
  return 5;
}
constexpr int kNoQuarter = 5;

// unwrapAngles' offset changes only at a step that rounds to a turn; steps
// within one of the safe quarters round to none (and subtracting 0
// from the offset, which is never -0, changes no bit), so their angles are
// not needed: only the ends' and those either side of any other step.
// Calls atStep(i, offset) for each i >= 1 with the offset there (n >= 1).
struct UnwrapWalk {
  double front = 0.0;   // the first point's angle
  double offset = 0.0;  // the offset at the last point
  bool lastKnown = true;
  double last = 0.0;  // the last point's angle, where lastKnown
};

template <class AtStep>
UnwrapWalk walkUnwrapAbout(std::span<const double> x, std::span<const double> y, std::size_t n, double cx, double cy,
                           AtStep atStep) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  UnwrapWalk walk;
  walk.front = walk.last = std::atan2(y[0] - cy, x[0] - cx);
  int previousQuarter = quarterOf(x[0] - cx, y[0] - cy);
  for (std::size_t i = 1; i < n; ++i) {
    const double dx = x[i] - cx, dy = y[i] - cy;
    const int quarter = quarterOf(dx, dy);
    if (quarter == previousQuarter && quarter != kNoQuarter) {
      walk.lastKnown = false;
    } else {
      if (!walk.lastKnown) walk.last = std::atan2(y[i - 1] - cy, x[i - 1] - cx);
      const double angle = std::atan2(dy, dx);
      walk.offset -= kTwoPi * std::round((angle - walk.last) / kTwoPi);
      walk.last = angle, walk.lastKnown = true;
    }
    atStep(i, walk.offset);
    previousQuarter = quarter;
  }
  return walk;
}

}  // namespace

std::vector<double> unwrapOffsetsAbout(std::span<const double> x, std::span<const double> y, double cx, double cy) {
  const std::size_t n = std::min(x.size(), y.size());
  std::vector<double> offsets(n, 0.0);
  if (n == 0) return offsets;
  walkUnwrapAbout(x, y, n, cx, cy, [&](std::size_t i, double offset) { offsets[i] = offset; });
  return offsets;
}

double sweptAngleAbout(std::span<const double> x, std::span<const double> y, double cx, double cy) {
  const std::size_t n = std::min(x.size(), y.size());
  if (n == 0) return 0.0;
  const UnwrapWalk walk = walkUnwrapAbout(x, y, n, cx, cy, [](std::size_t, double) {});
  const double back = walk.lastKnown ? walk.last : std::atan2(y[n - 1] - cy, x[n - 1] - cx);
  return (back + walk.offset) - walk.front;
}

}  // namespace hemiroll::analysis
