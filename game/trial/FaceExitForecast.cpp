#include "game/trial/FaceExitForecast.h"

#include <cmath>

#include "engine/physics/Orientation.h"

namespace hemiroll::game {

namespace {

constexpr double kSearchStep = 0.005;  // [s] between looks ahead; bisection then finds the crossing
constexpr int kBisections = 30;

}  // namespace

FaceExitForecast forecastFaceExit(const physics::ForceDrivenState& x, double radius, const physics::Vec2& a,
                                  const FaceExitForecastDef& def) {
  using namespace physics::force_slot;
  FaceExitForecast out;
  const physics::Vec2 p(x[x_p], x[y_p]), v(x[xd_p], x[yd_p]);
  const double edge = def.maxPointRadius * radius;
  if (!p.allFinite() || !v.allFinite() || !a.allFinite() || !(edge > 0.0) || !std::isfinite(edge)) return out;
  // At the present velocity: |p + v t| = edge, a quadratic with c <= 0
  // inside, so one root t >= 0.
  const double c = p.squaredNorm() - edge * edge;
  if (c >= 0.0) {
    out.timeToEdge = out.timeToEdgeAccelerating = 0.0;
    out.warn = true;
    return out;
  }
  const double vv = v.squaredNorm();
  if (vv > 0.0) {
    const double b = 2.0 * p.dot(v);
    out.timeToEdge = (-b + std::sqrt(b * b - 4.0 * vv * c)) / (2.0 * vv);
  }
  // With the acceleration held: a quartic; looked for in steps, then the
  // first crossing bisected.
  auto outside = [&](double t) { return (p + v * t + 0.5 * a * t * t).squaredNorm() >= edge * edge; };
  double before = 0.0;
  for (double t = kSearchStep; t <= def.accelerationHorizon + 1e-12; t += kSearchStep) {
    if (!outside(t)) {
      before = t;
      continue;
    }
    double after = t;
    for (int i = 0; i < kBisections; ++i) {
      const double mid = 0.5 * (before + after);
      (outside(mid) ? after : before) = mid;
    }
    out.timeToEdgeAccelerating = after;
    break;
  }
  out.warn = out.timeToEdge <= def.horizon || out.timeToEdgeAccelerating <= def.accelerationHorizon;
  return out;
}

physics::Vec2 faceAcceleration(const physics::ForceDrivenState& x, const physics::HemisphereParams& params,
                               const physics::Vec3& force) {
  using namespace physics::force_slot;
  if (!(params.pointMass > 0.0) || !force.allFinite()) return physics::Vec2::Zero();
  const physics::Mat3 R = physics::makeOrientation(x[u_o], x[v_o], x[psi]).R;  // face axes = its columns
  const physics::Vec3 total = force + physics::Vec3(0.0, 0.0, -params.pointMass * params.gravity);
  const physics::Vec2 a(total.dot(R.col(0)) / params.pointMass, total.dot(R.col(1)) / params.pointMass);
  return a.allFinite() ? a : physics::Vec2::Zero();
}

}  // namespace hemiroll::game
