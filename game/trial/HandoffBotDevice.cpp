#include "game/trial/HandoffBotDevice.h"

#include <algorithm>

#include "game/trial/BotDevice.h"

namespace hemiroll::game {

HandoffBotDevice::HandoffBotDevice(const haptics::DeviceSpec& spec, const haptics::WorkspaceMapping& mapping)
    : spec_(spec), mapping_(mapping) {}

haptics::DeviceReading HandoffBotDevice::read(double t) {
  haptics::DeviceReading r;
  Sample s;
  if (!samples_.read(s)) {
    r.fresh = false;  // nothing published yet
    return r;
  }
  const double ahead = std::clamp(t - s.time, 0.0, kMaxExtrapolation);
  const Vec3 velocity(s.velocity[0], s.velocity[1], s.velocity[2]);
  r.position = Vec3(s.position[0], s.position[1], s.position[2]) + ahead * velocity;
  r.velocity = t - s.time <= kMaxExtrapolation ? velocity : Vec3::Zero();
  r.fresh = t - s.time <= kStaleAfter;
  return r;
}

void HandoffBotDevice::send(double simTime, const Vec3& p, const Vec3& v) {
  Sample s;
  s.time = simTime;
  s.position = {p.x(), p.y(), p.z()};
  s.velocity = {v.x(), v.y(), v.z()};
  samples_.write(s);
  previous_ = s;
  hasPrevious_ = true;
}

void HandoffBotDevice::publish(double simTime, const Vec3& scenePosition) {
  bool limited = false;
  const Vec3 p = BotDevice::toDevice(scenePosition, mapping_, spec_, limited);
  Vec3 v = Vec3::Zero();
  if (hasPrevious_) {
    const double dt = simTime - previous_.time;
    const Vec3 last(previous_.position[0], previous_.position[1], previous_.position[2]);
    // The same observation answered twice (dt = 0): keep the last velocity.
    v = dt > 0.0 ? Vec3((p - last) / dt) : Vec3(previous_.velocity[0], previous_.velocity[1], previous_.velocity[2]);
  }
  send(simTime, p, limited ? Vec3::Zero() : v);
}

void HandoffBotDevice::publish(double simTime, const Vec3& scenePosition, const Vec3& sceneVelocity) {
  bool limited = false;
  const Vec3 p = BotDevice::toDevice(scenePosition, mapping_, spec_, limited);
  send(simTime, p, limited ? Vec3::Zero() : Vec3(sceneVelocity / mapping_.scale));
}

}  // namespace hemiroll::game
