#pragma once
// Where the person means the hand to be, tick by tick: the intent. A
// correction (a Movement) does not jump there; it is a submovement that
// blends from the running movement into the new one over its duration, on
// the minimum-jerk profile that human point-to-point moves follow, and the
// intent never moves faster than the hand can. A stir is a rhythmic
// movement: once started it goes round by itself (a pattern generator),
// corrections only move its centre, radius and pace.

#include "engine/physics/StateLayout.h"

namespace hemiroll::human {

struct Movement {
  enum class Kind { Hold, Stir };
  Kind kind = Kind::Hold;
  physics::Vec2 centre = physics::Vec2::Zero();  // Hold: the point; Stir: the ring's centre [m]
  double radius = 0.0;                           // Stir [m]
  double rate = 0.0;                             // Stir [rad/s], positive anticlockwise from above
};

class MotorPlan {
 public:
  // At rest at `at`; the intent's height stays there.
  void reset(const physics::Vec3& at);
  // A new correction, blended in over `duration` [s] (> 0).
  void start(const Movement& next, double duration);
  // One tick of `dt` [s], the intent's speed kept under `maxSpeed` [m/s].
  void advance(double dt, double maxSpeed);

  const physics::Vec3& position() const { return position_; }
  const physics::Vec3& velocity() const { return velocity_; }
  // The movement being blended in (or held).
  const Movement& target() const { return to_; }
  // The centre the running movement is at now [m].
  physics::Vec2 centre() const;

 private:
  double blend() const;  // 0 .. 1 along the submovement

  Movement from_, to_;
  double elapsed_ = 0.0, duration_ = 1.0;
  double phase_ = 0.0;
  double height_ = 0.0;
  physics::Vec3 position_ = physics::Vec3::Zero();
  physics::Vec3 velocity_ = physics::Vec3::Zero();
};

}  // namespace hemiroll::human
