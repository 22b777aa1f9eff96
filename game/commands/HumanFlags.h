#pragma once
// The human model's flags, shared by every command that can seat a
// simulated person (`run --bot human`, `session --bot human`):
//   --human-delay S       visual delay [s] (default 0.2)
//   --human-interval S    shortest time between corrections [s] (default 0.25)
//   --human-noise X       signal-dependent motor noise, SD per unit of move size (default 0.1)
//   --human-device D      mouse (default), mouse-hand (the game's simulated hand between mouse and proxy) or haptic
//   --human-aids          the game's aids on: the hint at a person's bandwidth, the force cue
//   --human-relaxed-arm   on a force device the arm stays relaxed (default: co-contracted)

#include <string>

#include "game/cli/ArgumentReader.h"
#include "game/trial/HumanBot.h"

namespace hemiroll::game {

void addHumanFlags(cli::ArgumentReader& reader, HumanBotOptions& options, std::string& device);
// After reading: "" or the sentence that says what is wrong.
std::string checkHumanFlags(HumanBotOptions& options, const std::string& device);

inline constexpr const char* kHumanFlagsUsage =
    "  --human-delay S    the human model's visual delay [s] (default 0.2)\n"
    "  --human-interval S its shortest time between two corrections [s] (default 0.25)\n"
    "  --human-noise X    its motor noise, SD per unit of move size (default 0.1)\n"
    "  --human-device D   what its hand holds: mouse (default), mouse-hand (the mouse through the\n"
    "                     game's simulated hand) or haptic\n"
    "  --human-aids       give it the game's aids (the hint, the force cue)\n"
    "  --human-relaxed-arm  on a force device its arm stays relaxed (300 N/m) instead of\n"
    "                     co-contracted (1000 N/m, docs/HUMAN_MODEL.md)\n";

}  // namespace hemiroll::game
