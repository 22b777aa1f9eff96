#include "engine/human/Technique.h"

#include <algorithm>
#include <cmath>

#include "engine/physics/PlaneVectors.h"

namespace hemiroll::human {

using physics::Vec2;

namespace {

// sin(tilt) towards the face's low side, as a vector on the floor [-].
Vec2 leanOf(const physics::Vec3& normal) { return {normal.x(), normal.y()}; }

}  // namespace

Vec2 uprightContactSeen(const ScreenView& view, double radius) {
  const double horizontal = std::hypot(view.normal.x(), view.normal.y());
  const double tilt = std::atan2(horizontal, view.normal.z());
  const double scale = horizontal > 1e-9 ? tilt / horizontal : 1.0;
  return view.contact - radius * scale * leanOf(view.normal);
}

Movement Technique::stir(const Vec2& error, double radius, double sense) const {
  // The drift runs about aimAngle from the aim, to the side the hemisphere
  // turns (measured: docs/HUMAN_MODEL.md); aim that far the other way. The
  // swirl goes round where it would stand upright, watched over a turn (it
  // rides a loop a turn), not round the contact, which swings a swirl's
  // width about it.
  const double distance = error.norm();
  const Vec2 towards = distance > 1e-9 ? Vec2(error / distance) : Vec2::Zero();
  const double aim = spinSeen_ >= 0.0 ? def_.aimAngle : -def_.aimAngle;
  Movement m;
  m.kind = Movement::Kind::Stir;
  m.centre = uprightSeen_ + std::min(def_.aimLimit, def_.aimGain * distance) * physics::turnedBy(towards, aim);
  m.radius = radius;
  m.rate = sense * def_.stirRate;
  return m;
}

void Technique::watch(const ScreenView& view, double interval) {
  const Vec2 upright = uprightContactSeen(view, radius_);
  const double tilt = std::atan2(std::hypot(view.normal.x(), view.normal.y()), view.normal.z());
  if (!watching_) {
    watching_ = true;
    uprightSeen_ = upright;
    tiltSeen_ = tilt;
    swirl_ = def_.stirRadius;
  }
  const double blend = std::min(1.0, interval / def_.uprightLag);
  uprightSeen_ += blend * (upright - uprightSeen_);
  tiltSeen_ += blend * (tilt - tiltSeen_);
  // The swirl's size follows the tilt gauge while it carries the hemisphere:
  // bigger while it leans less than swirlTilt, smaller while it leans more.
  if (phase_ == Phase::Stir)
    swirl_ = std::clamp(swirl_ * std::exp(def_.swirlGrowth * interval * (def_.swirlTilt - tiltSeen_) / def_.swirlTilt),
                        def_.swirlMin, def_.swirlMax);
}

Movement Technique::lean(const ScreenView& view) {
  // The mass point held R sin(tilt) off the face's centre leans the
  // hemisphere about that far; what that misses, the nudge makes up.
  const Vec2 want = leanOf(view.leanTarget);
  nudge_ = physics::limitedTo(nudge_ + def_.leanGain * (want - leanOf(view.normal)), 1.0);
  Movement m;
  m.kind = Movement::Kind::Hold;
  m.centre = view.contact + radius_ * physics::limitedTo(want + nudge_, 0.9);
  return m;
}

Movement Technique::leanOnto(const ScreenView& view) {
  nudge_ = physics::limitedTo(nudge_ + def_.nudgeGain * (view.contactTarget - view.contact), 0.5 * radius_);
  Movement m;
  m.kind = Movement::Kind::Hold;
  m.centre = view.contactTarget + nudge_;
  return m;
}

Movement Technique::settle(const ScreenView& view, const Vec2& upright, const Vec2& target) {
  if (view.contactTargetSet) nudge_ = physics::limitedTo(nudge_ + def_.nudgeGain * (view.contactTarget - view.contact), 0.5 * radius_);
  Movement m;
  m.kind = Movement::Kind::Hold;
  m.centre = upright + physics::limitedTo(target - upright, def_.holdReach) + nudge_;
  return m;
}

Movement Technique::turn(const ScreenView& view, double radius) {
  // An anticlockwise stir turns it clockwise; while the stir dies away it
  // keeps the sense it had.
  if (phase_ == Phase::Turn) turnSense_ = view.headingError < 0.0 ? 1.0 : -1.0;
  Movement m;
  m.kind = Movement::Kind::Stir;
  m.centre = view.contact;
  m.radius = radius;
  m.rate = turnSense_ * def_.stirRate;
  return m;
}

double Technique::brakeAbove(const ScreenView& view) const {
  return view.spinTolerance > 0.0 ? std::min(def_.brakeAbove, def_.brakeBand * view.spinTolerance) : def_.brakeAbove;
}

bool Technique::reachLeaning(const ScreenView& view) const {
  return view.contactTargetSet && !view.uprightRequired && !view.leanTargetSet &&
         (phase_ == Phase::Lean || (view.contactTarget - view.contact).norm() < def_.leanReach);
}

Movement Technique::hold(const ScreenView& view) {
  if (reachLeaning(view)) return leanOnto(view);
  const Vec2 upright = uprightContactSeen(view, radius_);
  return settle(view, upright, view.contactTargetSet ? view.contactTarget : upright);
}

Movement Technique::decide(const ScreenView& view, double interval) {
  spinSeen_ += std::min(1.0, interval / def_.spinLag) * (view.spin - spinSeen_);
  watch(view, interval);
  if (view.stage != stage_) {  // a new stage: start over from the stir (or the lean)
    stage_ = view.stage;
    phase_ = Phase::Stir;
    nudge_ = Vec2::Zero();
  }
  // A heading to reach and no contact to carry: stir on the spot until the
  // HUD's heading is well inside its band, then land as below.
  const double headingOff = view.headingSet ? std::abs(view.headingError) / view.headingTolerance : 0.0;
  if (view.headingSet && !view.contactTargetSet) {
    if (phase_ == Phase::Stir || phase_ == Phase::Lean) phase_ = Phase::Turn;
    if (phase_ == Phase::Settle && headingOff > def_.turnOutside) phase_ = Phase::Turn;
    if (phase_ == Phase::Turn) {
      if (headingOff > def_.turnInside) return turn(view, def_.stirRadius);
      phase_ = Phase::Land;
      fading_ = def_.stirRadius;
    }
  }
  if (view.leanTargetSet && !view.contactTargetSet && !view.headingSet) {
    phase_ = Phase::Lean;
    return lean(view);
  }
  if (reachLeaning(view)) {
    phase_ = Phase::Lean;
    return leanOnto(view);
  }
  const Vec2 upright = uprightContactSeen(view, radius_);
  const Vec2 target = view.contactTargetSet ? view.contactTarget : upright;
  const Vec2 error = target - upright;
  const double distance = error.norm();
  switch (phase_) {
    case Phase::Stir:
    case Phase::Lean:
      if (!view.contactTargetSet || distance < def_.landReach) {
        phase_ = Phase::Land;
        fading_ = view.contactTargetSet ? swirl_ : 0.0;
      }
      break;
    case Phase::Land:
      fading_ = std::max(0.0, fading_ - swirl_ * interval / def_.fadeTime);
      break;
    case Phase::Turn: break;
    case Phase::Settle:
      if (distance > def_.restirReach || view.time - settledAt_ > def_.settlePatience) {
        phase_ = Phase::Stir;
      } else if (view.time - settledAt_ > def_.brakeWait && std::abs(view.spin) > brakeAbove(view) &&
                 view.time - brakedAt_ > def_.brakeRest) {
        phase_ = Phase::Brake;
        brakeSense_ = view.spin > 0.0 ? 1.0 : -1.0;
        brakeEnds_ = view.time + def_.brakeTime;
        brakeSize_ = swirl_;
        fading_ = brakeSize_;
      }
      break;
    case Phase::Brake:
      if (view.time >= brakeEnds_) fading_ = std::max(0.0, fading_ - brakeSize_ * interval / def_.fadeTime);
      if (fading_ <= 0.0) {
        phase_ = Phase::Settle;
        settledAt_ = brakedAt_ = view.time;
      }
      break;
  }
  if (phase_ == Phase::Land && fading_ <= 0.0) {
    phase_ = Phase::Settle;
    settledAt_ = view.time;
    nudge_ = Vec2::Zero();
  }
  if (phase_ == Phase::Settle) return settle(view, upright, target);
  // Braking: a swirl in the sense it turns, on the spot.
  if (phase_ == Phase::Brake) return stir(Vec2::Zero(), fading_, brakeSense_);
  if (phase_ == Phase::Land && view.headingSet && !view.contactTargetSet) return turn(view, fading_);
  return stir(error, phase_ == Phase::Land ? fading_ : swirl_, 1.0);
}

}  // namespace hemiroll::human
