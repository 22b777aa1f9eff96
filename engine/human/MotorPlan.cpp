#include "engine/human/MotorPlan.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::human {

using physics::Vec2;
using physics::Vec3;

void MotorPlan::reset(const Vec3& at) {
  from_ = Movement{};
  from_.centre = at.head<2>();
  to_ = from_;
  elapsed_ = duration_ = 1.0;
  phase_ = 0.0;
  height_ = at.z();
  position_ = at;
  velocity_ = Vec3::Zero();
}

double MotorPlan::blend() const {
  const double tau = std::clamp(elapsed_ / duration_, 0.0, 1.0);
  return tau * tau * tau * (10.0 - 15.0 * tau + 6.0 * tau * tau);  // minimum jerk
}

Vec2 MotorPlan::centre() const {
  const double s = blend();
  return (1.0 - s) * from_.centre + s * to_.centre;
}

void MotorPlan::start(const Movement& next, double duration) {
  // The running movement, frozen where it is now, is where the new one starts.
  const double s = blend();
  Movement now;
  now.kind = to_.kind;
  now.centre = centre();
  const double radiusFrom = from_.kind == Movement::Kind::Stir ? from_.radius : 0.0;
  const double radiusTo = to_.kind == Movement::Kind::Stir ? to_.radius : 0.0;
  now.radius = (1.0 - s) * radiusFrom + s * radiusTo;
  now.rate = (1.0 - s) * from_.rate + s * to_.rate;
  from_ = now;
  to_ = next;
  if (to_.kind == Movement::Kind::Hold) to_.radius = 0.0, to_.rate = from_.rate;
  elapsed_ = 0.0;
  duration_ = duration;
}

void MotorPlan::advance(double dt, double maxSpeed) {
  elapsed_ += dt;
  const double s = blend();
  const double radiusFrom = from_.kind == Movement::Kind::Stir ? from_.radius : 0.0;
  const double radiusTo = to_.kind == Movement::Kind::Stir ? to_.radius : 0.0;
  const double radius = (1.0 - s) * radiusFrom + s * radiusTo;
  const double rate = (1.0 - s) * from_.rate + s * to_.rate;
  phase_ = std::remainder(phase_ + rate * dt, 2.0 * M_PI);
  const Vec2 c = centre();
  const Vec3 wanted(c.x() + radius * std::cos(phase_), c.y() + radius * std::sin(phase_), height_);
  Vec3 step = wanted - position_;
  const double most = maxSpeed * dt;
  if (step.norm() > most) step *= most / step.norm();
  position_ += step;
  velocity_ = step / dt;
}

}  // namespace hemiroll::human
