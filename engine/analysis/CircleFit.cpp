#include "engine/analysis/CircleFit.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <immintrin.h>

#include "engine/analysis/CpuLanes.h"

namespace hemiroll::analysis {

namespace {

// Two points at a time (CpuLanes.h's pairs), each lane the scalar
// operations of its point, so the same bits (issue 32: the fit of a sweep
// point's helix arc divided and took roots one value at a time, X and Y
// twice).
using Pair = DoublePair;
typedef long long PairBits __attribute__((vector_size(2 * sizeof(long long))));

// max(|x - mx|, |y - my|) over the points and 0, NaNs passed over, as
// std::max's chain from 0 does: the largest of values that are all +0 or
// more has one set of bits, whatever order they are taken in.
double largestOffset(std::span<const double> x, std::span<const double> y, std::size_t n, double mx, double my) {
  const PairBits magnitude = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL};
  Pair largest = {0.0, 0.0};
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) {
    for (const Pair v : {loadPair(&x[i]) - mx, loadPair(&y[i]) - my}) {
      const Pair a = (Pair)((PairBits)v & magnitude);
      largest = largest < a ? a : largest;
    }
  }
  double scale = std::max(largest[0], largest[1]);
  for (; i < n; ++i) scale = std::max({scale, std::abs(x[i] - mx), std::abs(y[i] - my)});
  return scale;
}

// X = (x - mx) / scale and Y likewise, each point's as the fit's loops take them.
void scaledCoordinates(std::span<const double> x, std::span<const double> y, std::size_t n, double mx, double my,
                       double scale, double* X, double* Y) {
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) {
    const Pair sx = (loadPair(&x[i]) - mx) / scale, sy = (loadPair(&y[i]) - my) / scale;
    storePair(X + i, sx);
    storePair(Y + i, sy);
  }
  for (; i < n; ++i) X[i] = (x[i] - mx) / scale, Y[i] = (y[i] - my) / scale;
}

// The squared distance d^2 of each point from the circle (Chernov's eq. 8.5
// in the Pratt form): d = 2 P / (1 + sqrt(max(0, 1 + 4 A P))).
void squaredDistances(const double* X, const double* Y, std::size_t n, double A, double B, double C, double D,
                      double* dd) {
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) {
    const Pair x = loadPair(X + i), y = loadPair(Y + i);
    const Pair P = A * (x * x + y * y) + B * x + C * y + D;
    const Pair inside = 1.0 + 4.0 * A * P;
    const Pair d = 2.0 * P / (1.0 + (Pair)_mm_sqrt_pd(0.0 < inside ? inside : Pair{0.0, 0.0}));  // std::max(0.0, inside)
    storePair(dd + i, d * d);
  }
  for (; i < n; ++i) {
    const double P = A * (X[i] * X[i] + Y[i] * Y[i]) + B * X[i] + C * Y[i] + D;
    const double d = 2.0 * P / (1.0 + std::sqrt(std::max(0.0, 1.0 + 4.0 * A * P)));
    dd[i] = d * d;
  }
}

}  // namespace

CircleFit fitCircle(std::span<const double> x, std::span<const double> y) {
  CircleFit fit;
  const std::size_t n = std::min(x.size(), y.size());
  if (n < 3) return fit;
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) mx += x[i], my += y[i];
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  // Moments about the centroid, scaled to O(1) so that the polynomial's
  // coefficients neither under- nor overflow for millimetre-sized data.
  const double scale = largestOffset(x, y, n, mx, my);
  if (!(scale > 0.0) || !std::isfinite(scale)) return fit;
  // The scaled coordinates, worked out once for both passes below, and the
  // squared distances (left uninitialised: each is written before it is read).
  const std::unique_ptr<double[]> scaled(new double[3 * n]);
  double* const X = scaled.get();
  double* const Y = X + n;
  scaledCoordinates(x, y, n, mx, my, scale, X, Y);
  double Mxx = 0, Myy = 0, Mxy = 0, Mxz = 0, Myz = 0, Mzz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double Z = X[i] * X[i] + Y[i] * Y[i];
    Mxx += X[i] * X[i], Myy += Y[i] * Y[i], Mxy += X[i] * Y[i], Mxz += X[i] * Z, Myz += Y[i] * Z, Mzz += Z * Z;
  }
  const double inv = 1.0 / static_cast<double>(n);
  Mxx *= inv, Myy *= inv, Mxy *= inv, Mxz *= inv, Myz *= inv, Mzz *= inv;
  const double Mz = Mxx + Myy;
  const double covXY = Mxx * Myy - Mxy * Mxy;
  // Collinear points (to round-off): the line through them, curvature 0.
  // Symmetric samples on a line make the circle's coefficients 0 / 0.
  const double minorVariance = 0.5 * (Mz - std::sqrt((Mxx - Myy) * (Mxx - Myy) + 4.0 * Mxy * Mxy));
  auto line = [&] {
    fit.ok = true;
    fit.rmsResidual = scale * std::sqrt(std::max(0.0, minorVariance));
    return fit;
  };
  if (minorVariance <= 1e-12 * Mz) return line();
  const double varZ = Mzz - Mz * Mz;
  const double A3 = 4.0 * Mz;
  const double A2 = -3.0 * Mz * Mz - Mzz;
  const double A1 = varZ * Mz + 4.0 * covXY * Mz - Mxz * Mxz - Myz * Myz;
  const double A0 = Mxz * (Mxz * Myy - Myz * Mxy) + Myz * (Myz * Mxx - Mxz * Mxy) - varZ * covXY;
  // Newton from 0: converges monotonically to the smallest root (Chernov).
  double root = 0.0, value = A0;
  for (int iter = 0; iter < 99; ++iter) {
    const double slope = A1 + root * (2.0 * A2 + 3.0 * A3 * root);
    if (slope == 0.0) break;
    const double next = root - value / slope;
    if (!std::isfinite(next)) break;
    const double nextValue = A0 + next * (A1 + next * (A2 + next * A3));
    if (std::abs(nextValue) >= std::abs(value) || std::abs(next - root) <= 1e-15 * std::abs(next)) {
      if (std::abs(nextValue) < std::abs(value)) root = next;
      break;
    }
    root = next, value = nextValue;
  }
  const double det = root * root - root * Mz + covXY;
  const double nx = Mxz * (Myy - root) - Myz * Mxy;
  const double ny = Myz * (Mxx - root) - Mxz * Mxy;
  // Pratt-normalised coefficients (scaled coordinates): A = det / S, B = -nx / S,
  // C = -ny / S, D = -Mz det / S with S^2 = nx^2 + ny^2 + 4 det^2 Mz.
  const double S = std::sqrt(nx * nx + ny * ny + 4.0 * det * det * Mz);
  if (!(S > 0.0) || !std::isfinite(S)) return line();
  const double A = det / S, B = -nx / S, C = -ny / S, D = -Mz * det / S;
  fit.ok = true;
  fit.curvature = 2.0 * std::abs(A) / scale;
  if (fit.curvature > 0.0) {
    fit.radius = 1.0 / fit.curvature;
    fit.centreX = mx + scale * nx / (2.0 * det);
    fit.centreY = my + scale * ny / (2.0 * det);
  }
  // Signed distance of a point from the circle in the Pratt form, stable as
  // A -> 0 (Chernov's eq. 8.5): d = 2 P / (1 + sqrt(1 + 4 A P)).
  double* const dd = Y + n;
  squaredDistances(X, Y, n, A, B, C, D, dd);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += dd[i];
  fit.rmsResidual = scale * std::sqrt(sum * inv);
  return fit;
}

}  // namespace hemiroll::analysis
