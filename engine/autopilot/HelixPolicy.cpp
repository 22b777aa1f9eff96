#include "engine/autopilot/HelixPolicy.h"

#include <algorithm>
#include <cmath>

#include "engine/autopilot/UprightContact.h"
#include "engine/physics/PlaneVectors.h"
#include "engine/physics/StateKinematics.h"

namespace hemiroll::autopilot {

using physics::Vec2;
using physics::Vec3;

namespace {
// The regulator's largest proxy speed: the planner's limit (Autopilot.cpp).
constexpr double kRegulatedSpeed = 0.25;  // [m/s]
// The regulator takes over below this tilt and this rocking (HelixPolicy::nearRest).
constexpr double kRegulateTilt = 0.1;     // [rad]
constexpr double kRegulateRocking = 0.2;  // [rad/s]
}  // namespace

HelixPolicy::HelixPolicy(const physics::ModelConstants& constants, const HelixParams& params, double dt)
    : constants_(&constants), params_(params), dt_(dt) {}

void HelixPolicy::setGoal(const Goal& goal) {
  goal_ = goal;
  // Upright at rest the mass point sits at p ~ R sin(tilt) for a contact
  // R tilt from c_up, so the bands on p and on u_co bound how far from c_up
  // the hemisphere may stand; 0.7 of the band leaves room for the wobble.
  const double R = constants_->params.radius;
  double reach = 0.5 * R;
  if (goal.set[0]) reach = std::min(reach, goal.tolerance[0]);
  if (goal.set[1]) reach = std::min(reach, goal.tolerance[1]);
  if (goal.set[9]) reach = std::min(reach, R * goal.tolerance[9]);
  if (goal.set[10]) reach = std::min(reach, R * goal.tolerance[10]);
  landReach_ = 0.7 * reach;
}

void HelixPolicy::startAt(const Vec3& proxy) {
  last_ = given_ = proxy;
  added_ = Vec3::Zero();
  regulating_ = false;
}

Vec2 LandingShape::at(double t) const {
  const double s = t / spacing;
  if (s < 0.0 || s >= kKnots) return Vec2::Zero();
  const int i = static_cast<int>(s);
  const double f = s - i;
  const Vec2 next = i + 1 < kKnots ? knots[static_cast<std::size_t>(i + 1)] : Vec2::Zero();
  return (1.0 - f) * knots[static_cast<std::size_t>(i)] + f * next;
}

void HelixPolicy::land(double landRate, double despinGain, const LandingShape& shape) {
  params_.landRate = landRate;
  params_.despinGain = despinGain;
  shape_ = shape;
  landingTime_ = 0.0;
  regulating_ = false;
  brakeLeft_ = 0.0;
  // A circle that never started has nothing to fade: settle at once, without
  // the steering offset's step (a kick a light mass point feels).
  if (phase_ == HelixPhase::Travel && radius_ <= 0.0) {
    phase_ = HelixPhase::Settle;
    return;
  }
  phase_ = HelixPhase::Land;
}

void HelixPolicy::brake(double amplitude, double rate, double lock) {
  travel();
  brakeAmplitude_ = amplitude;
  brakeRate_ = rate;
  brakeLeft_ = lock;
}

void HelixPolicy::travel() {
  phase_ = HelixPhase::Travel;
  brakeLeft_ = 0.0;
  regulating_ = false;
  detourZone_ = -1;
  shape_ = {};
  settleOffset_ = Vec2::Zero();
}

void HelixPolicy::reshape(const LandingShape& shape) {
  shape_ = shape;
  landingTime_ = 0.0;
}

void HelixPolicy::settleNow() {
  phase_ = HelixPhase::Settle;
  brakeLeft_ = 0.0;
  shape_ = {};
  landingTime_ = 0.0;
  radius_ = 0.0;
  regulating_ = false;
}

Vec2 HelixPolicy::contactTarget() const {
  return {goal_.set[7] ? goal_.target[7] : 0.0, goal_.set[8] ? goal_.target[8] : 0.0};
}

double HelixPolicy::contactBandError(const physics::ForceDrivenState& x) const {
  double worst = 0.0;
  for (const int slot : {physics::force_slot::u_a, physics::force_slot::v_a})
    if (goal_.set[slot]) worst = std::max(worst, std::abs(x[slot] - goal_.target[slot]) / goal_.tolerance[slot]);
  return worst;
}

Vec2 HelixPolicy::landingPoint(const Vec2& upright) const {
  if (!goal_.contactSet()) return upright;
  Vec2 want = contactTarget();
  if (!goal_.set[7]) want.x() = upright.x();
  if (!goal_.set[8]) want.y() = upright.y();
  return upright + physics::limitedTo(want - upright, landReach_);
}

Vec2 HelixPolicy::detour(const Vec2& contact, const Vec2& land) {
  // Settling rolls the contact straight to the landing point; a forbidden
  // zone in the way is passed on the side the contact is already on, at a
  // waypoint beside it (a box counts as its circle). A waypoint, once taken,
  // is kept until reached or until the straight path clears the zone by a
  // wider margin than the one that blocked it: a goal that flips between
  // the two every tick shakes the hemisphere.
  // How close the straight path passes the zone's centre; a path whose
  // nearest point is its end (a target just beside a zone) does not cross
  // it, however close that end is.
  const auto pathClearance = [&](const Vec2& centre) {
    const Vec2 path = land - contact;
    const double length = path.norm();
    if (length < 1e-9) return 1e30;
    const Vec2 along = path / length;
    const double s = (centre - contact).dot(along);
    if (s <= 0.0 || s >= length) return 1e30;
    return (contact + s * along - centre).norm();
  };
  const auto circleOf = [&](int i, Vec2& centre, double& radius) {
    const Zone& z = goal_.zones[static_cast<std::size_t>(i)];
    const Vec2 low(z.min[0], z.min[1]), high(z.max[0], z.max[1]);
    centre = z.circle ? Vec2(z.centre[0], z.centre[1]) : Vec2(0.5 * (low + high));
    radius = z.circle ? z.radius : 0.5 * (high - low).norm();
  };
  if (detourZone_ >= 0) {
    Vec2 centre;
    double radius = 0.0;
    circleOf(detourZone_, centre, radius);
    const bool reached = (waypoint_ - contact).norm() < 0.5 * radius;
    if (!reached && pathClearance(centre) < radius + 0.0006) return waypoint_;
    detourZone_ = -1;
  }
  for (int i = 0; i < goal_.zoneCount; ++i) {
    Vec2 centre;
    double radius = 0.0;
    circleOf(i, centre, radius);
    if (pathClearance(centre) >= radius + 0.0003) continue;  // the path clears it
    const Vec2 along = (land - contact).normalized();
    Vec2 side(-along.y(), along.x());
    if (side.dot(contact - centre) < 0.0) side = -side;
    const Vec2 waypoint = centre + (1.5 * radius + 0.001) * side;
    if ((waypoint - contact).norm() < 0.5 * radius) continue;  // already beside it
    detourZone_ = i;
    waypoint_ = waypoint;
    return waypoint;
  }
  return land;
}

Vec3 HelixPolicy::despin(const physics::ForceDrivenState& x) {
  const double spin = x[physics::force_slot::w_z];
  const double radius = std::min(params_.despinGain * std::abs(spin), params_.amplitude);
  despinAngle_ = std::remainder(despinAngle_ - std::copysign(std::abs(params_.rate), spin) * dt_, 2.0 * M_PI);
  return {radius * std::cos(despinAngle_), radius * std::sin(despinAngle_), 0.0};
}

bool HelixPolicy::leansOnly() const { return !goal_.contactSet() && (goal_.set[9] || goal_.set[10]); }

Vec3 HelixPolicy::leanGoal(const physics::ForceDrivenState& x) {
  // The lean as a horizontal vector of angles, pointing to the low side:
  // (-u_o, v_o) (a mass point at +x leans it to +x with u_o < 0). A slot
  // the stage leaves free keeps its present value.
  using namespace physics::force_slot;
  const physics::HemisphereParams& p = constants_->params;
  const Vec2 lean(-x[u_o], x[v_o]);
  const Vec2 want(goal_.set[u_o] ? -goal_.target[u_o] : lean.x(), goal_.set[v_o] ? goal_.target[v_o] : lean.y());
  // At rest at tilt t the mass point sits d = R sin t + (3R/8)(m_s/m_p) tan t
  // towards the low side of the face's centre (the weights' moments about
  // the contact balance: m_p cos t (d - R sin t) = (3R/8) m_s sin t), and the
  // face's centre stands over the contact point. The spring's sag and the
  // hand's softening are left to the integral, which turns the lean's
  // error into a further offset.
  const double t = std::min(want.norm(), 1.2);
  const Vec2 towards = want.norm() > 1e-12 ? Vec2(want / want.norm()) : Vec2::Zero();
  const double d = p.radius * std::sin(t) + 0.375 * p.radius * (p.shellMass / p.pointMass) * std::tan(t);
  settleOffset_ += physics::limitedTo(params_.settleGain * p.radius * (want - lean), params_.glideSpeed) * dt_;
  settleOffset_ = physics::limitedTo(settleOffset_, 0.5 * p.radius);
  const Vec2 at = Vec2(x[u_a], x[v_a]) + d * std::cos(t) * towards + settleOffset_;
  return {at.x(), at.y(), p.radius - d * std::sin(t)};
}

Vec3 HelixPolicy::proxyFor(const physics::ForceDrivenState& x) {
  using namespace physics::force_slot;
  const double R = constants_->params.radius;
  const UprightContact up = uprightContact(*constants_, x);
  Vec3 proxy;
  const bool mayRegulate = phase_ == HelixPhase::Settle && settleGain_.valid && regulatorOn_ && goal_.zoneCount == 0 &&
                           (regulating_ || nearRest(x, up.tilt));
  if (mayRegulate && regulateLean_ && leansOnly()) {
    // A lean asked for: the regulator holds the rest at that lean (on the
    // paper's light shell the glide below left the hemisphere rocking at
    // 0.1-0.15 rad/s round upright, outside an |omega| band of 0.02).
    using namespace physics::force_slot;
    const Vec2 want(goal_.set[u_o] ? -goal_.target[u_o] : -x[u_o], goal_.set[v_o] ? goal_.target[v_o] : x[v_o]);
    const double t = std::min(want.norm(), 1.2);
    const Vec2 lean = t > 1e-12 ? Vec2(std::sin(t) / want.norm() * want) : Vec2::Zero();
    proxy = regulatedSettle(x, lean, up.point + R * t * (t > 1e-12 ? Vec2(want / want.norm()) : Vec2::Zero()));
  } else if (phase_ == HelixPhase::Settle && leansOnly()) {
    // Glide to the lean's goal at the settle's speed, as below.
    const Vec3 goal = leanGoal(x);
    motion_.goal = goal.head<2>();
    Vec3 step = goal - last_;
    const double most = params_.glideSpeed * dt_;
    if (step.norm() > most) step *= most / step.norm();
    proxy = last_ + step;
  } else if (mayRegulate && !leansOnly()) {
    const Vec2 land = landingPoint(up.point);
    const Vec2 away = land - up.point;
    const double tilt = away.norm() / R;
    proxy = regulatedSettle(x, tilt > 1e-12 ? Vec2(std::sin(tilt) / away.norm() * away) : Vec2::Zero(), land);
  } else if (phase_ == HelixPhase::Settle) {
    regulating_ = false;
    const Vec2 land = detour(Vec2(x[u_a], x[v_a]), landingPoint(up.point));
    const Vec2 error = land - Vec2(x[u_a], x[v_a]);
    // The goal creeps only while the contact is not yet well inside its
    // band: a proxy that keeps creeping keeps the hemisphere rocking, and in
    // real time (plans handed over at 500 Hz) that rocking sat at the edge
    // of the |omega| band for a whole trial (tutorial 02, 2 of 6 runs).
    // Full gain beyond 0.8 of the band, none within 0.4, linear between, so
    // that nothing switches.
    const double creep = goal_.contactSet() ? std::clamp((contactBandError(x) - 0.4) / 0.4, 0.0, 1.0) : 1.0;
    settleOffset_ += physics::limitedTo(creep * params_.settleGain * error, params_.glideSpeed) * dt_;
    settleOffset_ = physics::limitedTo(settleOffset_, 0.5 * R);
    const Vec3 goal(land.x() + settleOffset_.x(), land.y() + settleOffset_.y(), R);
    motion_.goal = goal.head<2>();
    Vec3 step = goal - last_;
    const double most = params_.glideSpeed * dt_;
    if (step.norm() > most) step *= most / step.norm();
    proxy = last_ + step;
  } else {
    Vec2 error = Vec2::Zero();
    const bool braking = brakeLeft_ > 0.0;
    if (goal_.contactSet() && !braking) {
      error = contactTarget() - up.point;
      if (!goal_.set[7]) error.x() = 0.0;
      if (!goal_.set[8]) error.y() = 0.0;
    }
    const Vec2 steer = physics::limitedTo(params_.steerGain * physics::turnedBy(error, params_.steerAngle), params_.steerLimit);
    const bool circling = phase_ == HelixPhase::Travel;
    const double amplitude = braking ? brakeAmplitude_ : params_.amplitude;
    const double pace = braking ? brakeRate_ : params_.rate;
    const double rate = circling ? amplitude : params_.landRate;  // [m/s] of radius change
    const double want = circling ? amplitude : 0.0;
    radius_ += std::clamp(want - radius_, -rate * dt_, rate * dt_);
    phaseAngle_ = std::remainder(phaseAngle_ + pace * dt_, 2.0 * M_PI);
    proxy = Vec3(x[u_a] + steer.x() + radius_ * std::cos(phaseAngle_),
                 x[v_a] + steer.y() + radius_ * std::sin(phaseAngle_), R);

    motion_.centre = Vec2(x[u_a] + steer.x(), x[v_a] + steer.y());
    motion_.radius = radius_;
    motion_.rate = pace;
    if (phase_ == HelixPhase::Land && radius_ <= 0.0) phase_ = HelixPhase::Settle;
    // The brake stops dead: the spin it leaves is the stop's (SpinBrake.h).
    if (braking && (brakeLeft_ -= dt_) <= 0.0) {
      brakeLeft_ = 0.0;
      radius_ = 0.0;
      phase_ = HelixPhase::Settle;
    }
  }
  // last_ keeps the path; the landing shape rides on it.
  last_ = proxy;
  motion_.phase = phase_;
  added_ = Vec3::Zero();
  if (phase_ != HelixPhase::Travel) {
    const Vec2 shaped = shape_.at(landingTime_);
    landingTime_ += dt_;
    added_ = despin(x) + Vec3(shaped.x(), shaped.y(), 0.0);
  }
  // The regulator's proxy is the device's own: its model has the level's
  // coupling, so the hand does not stiffen it.
  given_ = regulating_ ? Vec3(proxy + added_) : stiffened(proxy + added_, x);
  return given_;
}

bool HelixPolicy::nearRest(const physics::ForceDrivenState& x, double tilt) const {
  // The regulator is linear about a rest: taking over from a landing still
  // tilted 0.1-0.4 rad and rocking, it threw the paper's hemisphere off or
  // left it spinning at 0.16 rad/s (measured), so the glide brings it near
  // first.
  using namespace physics::force_slot;
  return tilt < kRegulateTilt && std::hypot(x[w_x], x[w_y]) < kRegulateRocking;
}

Vec3 HelixPolicy::regulatedSettle(const physics::ForceDrivenState& x, const Vec2& lean, const Vec2& goal) {
  // The regulator's path starts where the proxy is (less what rides on it).
  if (!regulating_) {
    last_ = given_ - added_;
    regulating_ = true;
  }
  // At most the planner's proxy speed (Autopilot's deliverable()).
  const Vec2 step = settleStep(settleGain_, *constants_, x, given_.head<2>(), lean, kRegulatedSpeed * dt_);
  motion_.goal = goal;
  return {last_.x() + step.x(), last_.y() + step.y(), settleGain_.proxyHeight};
}

Vec3 HelixPolicy::stiffened(const Vec3& proxy, const physics::ForceDrivenState& x) const {
  if (params_.stiffen == 0.0) return proxy;
  const Vec3 mass = physics::massPointPosition(x, constants_->params.radius);
  return proxy + params_.stiffen * (proxy - mass);
}

}  // namespace hemiroll::autopilot
