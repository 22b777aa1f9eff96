#include "game/trial/FaceExitForecast.h"

#include <cmath>

namespace hemiroll::game {

FaceExitForecast forecastFaceExit(const physics::ForceDrivenState& x, double radius, const FaceExitForecastDef& def) {
  using namespace physics::force_slot;
  FaceExitForecast out;
  const double px = x[x_p], py = x[y_p], vx = x[xd_p], vy = x[yd_p];
  const double edge = def.maxPointRadius * radius;
  if (!std::isfinite(px) || !std::isfinite(py) || !std::isfinite(vx) || !std::isfinite(vy) || !(edge > 0.0))
    return out;
  // |p + v t| = edge: a t^2 + b t + c = 0 with c <= 0 inside, one root t >= 0.
  const double c = px * px + py * py - edge * edge;
  if (c >= 0.0) {
    out.timeToEdge = 0.0;
  } else {
    const double a = vx * vx + vy * vy;
    if (!(a > 0.0)) return out;
    const double b = 2.0 * (px * vx + py * vy);
    out.timeToEdge = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  }
  out.warn = out.timeToEdge <= def.horizon;
  return out;
}

}  // namespace hemiroll::game
