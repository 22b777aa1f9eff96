#include "engine/human/HumanModel.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace hemiroll::human {

using physics::Vec2;
using physics::Vec3;

HumanModel::HumanModel(const HumanDef& def, const TechniqueDef& technique, double radius, double tick,
                       std::uint64_t seed)
    : def_(def), tick_(tick), delay_(def.visualDelay, tick), technique_(technique, radius), limb_(holdingLimb(def)),
      normal_(seed ^ 0x6875'6d61'6e00'0000ULL) {}

void HumanModel::takeHold(const Vec3& at) {
  plan_.reset(at);
  limb_.reset(at);
}

Movement HumanModel::decide(const ScreenView& seen) {
  const HintCue& hint = seen.hint;
  Movement m;
  // A target the person can lean onto needs no hint; the hint is for what
  // leaning cannot do.
  if (technique_.reachLeaning(seen)) return technique_.decide(seen, def_.interval);
  switch (hint.kind) {
    case HintKind::Stir:
      ++stats_.hintCorrections;
      m.kind = Movement::Kind::Stir;
      m.centre = hint.centre;
      m.radius = hint.radius;
      m.rate = hint.rate;
      return m;
    case HintKind::Settle:
      ++stats_.hintCorrections;
      m.kind = Movement::Kind::Hold;
      m.centre = hint.point;
      return m;
    case HintKind::None: break;
  }
  return technique_.decide(seen, def_.interval);
}

Movement HumanModel::withNoise(Movement m) {
  // Signal-dependent noise: the end of a move scatters in proportion to its
  // size, over a floor that a still hand has too.
  const double size = (m.centre - plan_.centre()).norm();
  const double spread = std::hypot(def_.noise * size, def_.steadiness);
  m.centre += spread * Vec2(normal_(), normal_());
  if (m.kind == Movement::Kind::Stir) {
    m.radius = std::max(0.0, m.radius * (1.0 + def_.noise * normal_()));
    m.rate *= 1.0 + def_.noise * normal_();
  }
  return m;
}

bool HumanModel::worthCorrecting(const Movement& wanted) const {
  const Movement& doing = plan_.target();
  if (wanted.kind != doing.kind || stats_.corrections == 0) return true;
  if ((wanted.centre - doing.centre).norm() > def_.deadZone) return true;
  if (wanted.kind == Movement::Kind::Stir &&
      (std::abs(wanted.radius - doing.radius) > def_.deadZone || std::abs(wanted.rate - doing.rate) > 0.1 * std::abs(doing.rate)))
    return true;
  return false;
}

HandPose HumanModel::act(const ScreenView& now, const Vec3& deviceForce) {
  const ScreenView* seen = delay_.push(now);
  if (seen != nullptr && now.time - lastDecision_ >= def_.interval - 0.5 * tick_) {
    lastDecision_ = now.time;
    const Movement wanted = decide(*seen);
    if (worthCorrecting(wanted)) {
      const double lag = now.time - seen->time;
      stats_.largestLag = std::max(stats_.largestLag, lag);
      stats_.smallestLag = std::min(stats_.smallestLag, lag);
      if (stats_.corrections > 0) stats_.shortestInterval = std::min(stats_.shortestInterval, now.time - lastCorrection_);
      else stats_.firstCorrection = now.time;
      ++stats_.corrections;
      lastCorrection_ = now.time;
      plan_.start(withNoise(wanted), def_.interval);
    }
  }
  plan_.advance(tick_, def_.maxSpeed);
  const Vec3 push = def_.device == HandDevice::Haptic ? deviceForce : Vec3::Zero();
  limb_.step(plan_.position(), plan_.velocity(), push, tick_);
  return {limb_.position(), limb_.velocity()};
}

const char* handDeviceName(HandDevice device) {
  switch (device) {
    case HandDevice::Haptic: return "haptic";
    case HandDevice::MouseHand: return "mouse-hand";
    case HandDevice::Mouse: break;
  }
  return "mouse";
}

bool parseHandDevice(const char* name, HandDevice& out) {
  const std::string_view n(name);
  if (n == "mouse") out = HandDevice::Mouse;
  else if (n == "haptic") out = HandDevice::Haptic;
  else if (n == "mouse-hand") out = HandDevice::MouseHand;
  else return false;
  return true;
}

}  // namespace hemiroll::human
