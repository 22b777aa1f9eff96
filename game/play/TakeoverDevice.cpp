#include "game/play/TakeoverDevice.h"

namespace hemiroll::game {

haptics::DeviceReading TakeoverDevice::read(double t) {
  haptics::DeviceReading player = player_.read(t);
  if (!playerHolds()) return autopilot_.read(t);
  player.newPath = !announced_;  // the switch is no motion of the hand
  announced_ = true;
  return player;
}

void TakeoverDevice::sendForce(const haptics::Vec3& force) {
  player_.sendForce(playerHolds() ? force : haptics::Vec3::Zero());
}

}  // namespace hemiroll::game
