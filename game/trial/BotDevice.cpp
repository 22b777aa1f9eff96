#include "game/trial/BotDevice.h"

namespace hemiroll::game {

BotDevice::BotDevice(const haptics::DeviceSpec& spec, const haptics::WorkspaceMapping& mapping, double tickPeriod)
    : spec_(spec), mapping_(mapping), period_(tickPeriod) {}

haptics::DeviceReading BotDevice::read(double) { return reading_; }

namespace {
// Beyond this a pose only says "far away": clamping the components first
// keeps the mapping and the norm below from overflowing to inf [m].
constexpr double kFar = 1e6;
}  // namespace

Vec3 BotDevice::toDevice(const Vec3& scenePosition, const haptics::WorkspaceMapping& mapping,
                         const haptics::DeviceSpec& spec, bool& limited) {
  const Vec3 bounded = scenePosition.cwiseMax(-kFar).cwiseMin(kFar);
  Vec3 p = (bounded - mapping.offset) / mapping.scale;
  const double reach = p.norm();
  limited = reach > spec.workspaceRadius;
  if (limited) p *= spec.workspaceRadius / reach;
  return p;
}

void BotDevice::setPose(const Vec3& scenePosition) {
  const Vec3 p = toDevice(scenePosition, mapping_, spec_, limited_);
  reading_.velocity = hasPose_ ? Vec3((p - reading_.position) / period_) : Vec3::Zero();
  reading_.position = p;
  hasPose_ = true;
}

void BotDevice::setPose(const Vec3& scenePosition, const Vec3& sceneVelocity) {
  reading_.position = toDevice(scenePosition, mapping_, spec_, limited_);
  // At the stop the device does not move outwards, whatever the bot says.
  reading_.velocity = limited_ ? Vec3::Zero() : Vec3(sceneVelocity / mapping_.scale);
  hasPose_ = true;
}

}  // namespace hemiroll::game
