#pragma once
// The device of "watch the autopilot": the autopilot's hand (a
// HandoffBotDevice fed by the AutopilotCompanion) holds the proxy until the
// player takes over; from then on the player's own device does, for good.
// The switch is one atomic flag the servo thread reads every tick. While the
// autopilot holds, the player's device is still read (a bridge's watchdog
// stays fed) but feels nothing: the autopilot's forces are not the player's.

#include <atomic>
#include <memory>

#include "engine/haptics/HapticDevice.h"
#include "game/trial/HandoffBotDevice.h"

namespace hemiroll::game {

class TakeoverDevice final : public haptics::HapticDevice {
 public:
  // Both must outlive this device.
  TakeoverDevice(HandoffBotDevice& autopilot, haptics::HapticDevice& player) : autopilot_(autopilot), player_(player) {}
  // Owns both (the one device a TrialRig owns).
  TakeoverDevice(std::unique_ptr<HandoffBotDevice> autopilot, std::unique_ptr<haptics::HapticDevice> player)
      : ownedAutopilot_(std::move(autopilot)),
        ownedPlayer_(std::move(player)),
        autopilot_(*ownedAutopilot_),
        player_(*ownedPlayer_) {}

  const haptics::DeviceSpec& spec() const override { return player_.spec(); }
  bool open() override { return player_.open(); }
  void close() override { player_.close(); }
  bool ready() const override { return player_.ready(); }
  haptics::DeviceReading read(double t) override;
  void sendForce(const haptics::Vec3& force) override;
  const char* error() const override { return player_.error(); }

  // Any thread: the player holds from the next tick on.
  void handToPlayer() { playerHolds_.store(true, std::memory_order_release); }
  bool playerHolds() const { return playerHolds_.load(std::memory_order_acquire); }

 private:
  std::unique_ptr<HandoffBotDevice> ownedAutopilot_;  // null when not owned
  std::unique_ptr<haptics::HapticDevice> ownedPlayer_;
  HandoffBotDevice& autopilot_;
  haptics::HapticDevice& player_;
  std::atomic<bool> playerHolds_{false};
  bool announced_ = false;  // servo thread: the first player reading said newPath
};

}  // namespace hemiroll::game
