#include "game/commands/HumanFlags.h"

namespace hemiroll::game {

void addHumanFlags(cli::ArgumentReader& reader, HumanBotOptions& o, std::string& device) {
  reader.option("--human-delay", cli::numberIn(o.human.visualDelay, 0.0, 2.0, "a delay from 0 to 2 s"))
      .option("--human-interval", cli::numberIn(o.human.interval, 0.001, 5.0, "an interval from 0.001 to 5 s"))
      .option("--human-noise", cli::numberIn(o.human.noise, 0.0, 1.0, "a noise level from 0 to 1"))
      .option("--human-device", cli::text(device, "mouse, mouse-hand or haptic"))
      .flag("--human-aids", [&o] { o.aids = true; })
      .flag("--human-relaxed-arm", [&o] { o.human.coContracts = false; });
}

std::string checkHumanFlags(HumanBotOptions& o, const std::string& device) {
  if (device.empty()) return {};
  if (!human::parseHandDevice(device.c_str(), o.human.device))
    return "--human-device needs mouse, mouse-hand or haptic, not '" + device + "'";
  return {};
}

}  // namespace hemiroll::game
