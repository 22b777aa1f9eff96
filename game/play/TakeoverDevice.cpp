#include "game/play/TakeoverDevice.h"

namespace hemiroll::game {

haptics::DeviceReading TakeoverDevice::read(double t) {
  const haptics::DeviceReading player = player_.read(t);
  return playerHolds() ? player : autopilot_.read(t);
}

void TakeoverDevice::sendForce(const haptics::Vec3& force) {
  player_.sendForce(playerHolds() ? force : haptics::Vec3::Zero());
}

}  // namespace hemiroll::game
