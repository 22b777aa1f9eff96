#include "engine/analysis/CircleFit.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::analysis {

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
  double scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) scale = std::max({scale, std::abs(x[i] - mx), std::abs(y[i] - my)});
  if (!(scale > 0.0) || !std::isfinite(scale)) return fit;
  double Mxx = 0, Myy = 0, Mxy = 0, Mxz = 0, Myz = 0, Mzz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double X = (x[i] - mx) / scale, Y = (y[i] - my) / scale, Z = X * X + Y * Y;
    Mxx += X * X, Myy += Y * Y, Mxy += X * Y, Mxz += X * Z, Myz += Y * Z, Mzz += Z * Z;
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
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double X = (x[i] - mx) / scale, Y = (y[i] - my) / scale;
    const double P = A * (X * X + Y * Y) + B * X + C * Y + D;
    const double d = 2.0 * P / (1.0 + std::sqrt(std::max(0.0, 1.0 + 4.0 * A * P)));
    sum += d * d;
  }
  fit.rmsResidual = scale * std::sqrt(sum * inv);
  return fit;
}

}  // namespace hemiroll::analysis
