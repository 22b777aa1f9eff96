#include "game/commands/RunOptions.h"

#include <string>

#include "engine/physics/ForceCoupling.h"
#include "engine/haptics/devices/DeviceNames.h"

#include "game/cli/ArgumentReader.h"
#include "game/commands/HumanFlags.h"

namespace hemiroll::game {

const char* runUsage() {
  static const std::string usage = std::string(
         "usage: hemiroll run LEVEL.lua --bot BOT.lua|autopilot|passive-hand|human [--seed N] [--record DIR]\n"
         "                    [--realtime] [--device-profile NAME]\n"
         "                    [--autopilot-budget X] [--guidance KIND [--guidance-stiffness K]\n"
         "                    [--guidance-damping C]] [--human-delay S] [--human-interval S]\n"
         "                    [--human-noise X] [--human-device mouse|mouse-hand|haptic] [--human-aids]\n"
         "                    [--human-relaxed-arm]\n"
         "       hemiroll run LEVEL.lua --realtime --device udp [--port N] [--device-profile NAME]\n"
         "\n"
         "Plays a level with a bot (a Lua module, e.g. scripts/bots/rose.lua) and prints one\n"
         "JSON line: level, bot, outcome, reason, time, score, medal, ticks, wall_time\n"
         "(docs/RUN.md). Headless and as fast as the CPU allows unless --realtime;\n"
         "the same level, bot and seed give the same result bit for bit.\n"
         "\n"
         "  --bot BOT.lua   the bot that plays (required); \"autopilot\" is the built-in\n"
         "                  planner (docs/AUTOPILOT.md), \"passive-hand\" a hand that only\n"
         "                  yields to the device's force, \"human\" a simulated person\n"
         "                  (docs/HUMAN_MODEL.md)\n"
         "  --autopilot-budget X  the autopilot's planning effort, 0.25 to 4 (default 1):\n"
         "                  more tries per decision and a longer look ahead\n"
         "  --seed N        seed of the level's and the bot's hemiroll.random and the\n"
         "                  bot's init (0 .. 9223372036854775807; default 0)\n"
         "  --record DIR    record the trial into DIR (per-trial CSV + JSON sidecar and\n"
         "                  results.csv, docs/RECORDING.md)\n"
         "  --realtime      pace the servo ticks at 1 kHz on the wall clock\n"
         "  --device-profile NAME  hold the trial to a device's limits: NAME.lua in\n"
         "                  devices/ (generic, touch, touch_x, omega3, omega6, falcon,\n"
         "                  inverse3) or a profile file (docs/UDP_BRIDGE.md)\n"
         "  --device udp    a person plays at a real haptic device behind the UDP bridge\n"
         "                  (its client sends to 127.0.0.1:PORT; needs --realtime, no --bot)\n"
         "  --port N        the bridge's port (default 47110)\n"
         "  --client-timeout S  how long to wait for the device's first state (default 30 s)\n"
         "  --guidance KIND haptic guidance: \"autopilot\" pulls the device towards the\n"
         "                  autopilot's plan, \"error_augmentation\" pushes it away,\n"
         "                  \"none\" (default); try it with --bot passive-hand\n"
         "  --guidance-stiffness K  the guidance spring [N/m] (default 200)\n"
         "  --guidance-damping C    the guidance damper [N s/m] (default 10)\n"
         "  --help          print this help\n") + kHumanFlagsUsage + std::string(
         "\n"
         "Exit codes: 0 success, 1 failure (the trial failed, or the recording could not\n"
         "be written), 2 bad input (a flag, or a level or bot that cannot be loaded).\n");
  return usage.c_str();
}

RunOptionsResult parseRunOptions(const std::vector<std::string>& args) {
  RunOptionsResult result;
  RunOptions& o = result.options;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .flag("--realtime", [&] { o.realtime = true; })
      .positional("level file", 1, [&](const std::string& path) { o.levelPath = path; })
      .option("--bot", cli::text(o.botPath, "a bot file"))
      .option("--record", cli::text(o.recordDir, "a directory"))
      .option("--device-profile", cli::text(o.deviceProfile, "a device profile name or file"))
      .option("--device", cli::text(o.device, "bot or udp"))
      .option("--port", cli::integerIn(o.port, 1, 65535, "a port from 1 to 65535"))
      .option("--client-timeout", cli::numberIn(o.clientTimeout, 0.001, 3600.0, "seconds from 0.001 to 3600"))
      .option("--guidance", cli::text(o.guidance, "none, autopilot or error_augmentation"))
      // The bounds a protocol's guidance has (one rule: 0 is allowed for both).
      .option("--guidance-stiffness",
              cli::numberIn(o.guidanceStiffness, 0.0, physics::kMaxStiffness, "a stiffness from 0 to 1e6 N/m"))
      .option("--guidance-damping",
              cli::numberIn(o.guidanceDamping, 0.0, physics::kMaxDamping, "a damping from 0 to 1e4 N s/m"))
      .option("--autopilot-budget", cli::positiveNumber(o.autopilotBudget, "a planning effort from 0.25 to 4"))
      // Lua integers are signed 64-bit, and the bot receives the seed as one.
      .option("--seed", cli::unsignedUpTo(o.seed, 0x7fffffffffffffffULL, "a whole number from 0 to 9223372036854775807"));
  addHumanFlags(reader, o.human, o.humanDevice);
  result.error = reader.read(args);
  if (!result.error.empty() || o.help) return result;
  if (o.levelPath.empty()) result.error = "missing the level file";
  else if (o.device != "bot" && o.device != haptics::kUdpDevice)
    result.error = "--device needs bot or udp, not '" + o.device + "'";
  else if (o.device == haptics::kUdpDevice && !o.realtime)
    result.error = "--device udp needs --realtime: a person at a device plays on the wall clock";
  else if (o.device == haptics::kUdpDevice && !o.botPath.empty())
    result.error = "--device udp and --bot exclude each other: the person at the device plays";
  else if (o.device == haptics::kUdpDevice && o.guidance != "none")
    result.error = "--guidance needs a bot (the autopilot plans beside it); not with --device udp";
  else if (o.device == "bot" && o.botPath.empty()) result.error = "missing --bot BOT.lua";
  else if (o.autopilotBudget < 0.25 || o.autopilotBudget > 4.0)
    result.error = "--autopilot-budget needs a planning effort from 0.25 to 4";
  else if (o.guidance != "none" && o.guidance != "autopilot" && o.guidance != "error_augmentation")
    result.error = "--guidance needs none, autopilot or error_augmentation, not '" + o.guidance + "'";
  else
    result.error = checkHumanFlags(o.human, o.humanDevice);
  return result;
}

}  // namespace hemiroll::game
