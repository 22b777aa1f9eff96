#include "game/commands/SessionOptions.h"

#include "game/cli/ArgumentReader.h"
#include "game/commands/HumanFlags.h"
#include "engine/haptics/devices/DeviceNames.h"

#include <string>

namespace hemiroll::game {

const char* sessionUsage() {
  static const std::string text = std::string("usage: hemiroll session PROTOCOL.lua --participant ID [--session ID] [--data DIR]\n"
         "                        [--bot BOT.lua] [--seed N] [--levels DIR]\n"
         "                        [--device-profile NAME] [--device udp [--port N]]\n"
         "       hemiroll session PROTOCOL.lua --participants N --bot BOT [--participant PREFIX] ...\n"
         "\n"
         "Runs a research protocol (docs/PROTOCOLS.md) for one participant: every trial of\n"
         "its plan is recorded into DIR/<experiment>/<participant>/<session>/ (trial CSV +\n"
         "sidecar, results.csv after every trial, session.json). With --bot a bot plays\n"
         "every trial headless and one JSON line per trial is printed as it finishes, then\n"
         "a summary line. Running the same session again resumes it after the last\n"
         "finished trial; an interrupted trial's files are moved aside, never deleted.\n"
         "People play sessions in the game window (hemiroll play, Research session).\n"
         "\n"
         "  --participant ID  who plays (letters, digits, '-', '_'; required)\n"
         "  --session ID      the session id (default 1); a new id starts a new session\n"
         "  --data DIR        the data root (default: the game's data directory/sessions)\n"
         "  --bot BOT.lua     the bot that plays every trial (e.g. scripts/bots/tutorial_solver.lua)\n"
         "  --seed N          the plan's randomisation seed (0 .. 9223372036854775807;\n"
         "                    default: the protocol's; a resumed session keeps its own)\n"
         "  --levels DIR      where level files are looked for after the protocol's folder\n"
         "                    (default: the folder named levels that holds the protocol)\n"
         "  --device-profile NAME  the device's limits (devices/NAME.lua or a file;\n"
         "                    docs/UDP_BRIDGE.md); default: the protocol's device_profile\n"
         "  --device udp      a participant at a real haptic device behind the UDP bridge\n"
         "                    plays every trial, without a window (docs/UDP_BRIDGE.md);\n"
         "                    the trial lines name any stop and the packet counts\n"
         "  --port N          the bridge's port (default 47110)\n"
         "  --client-timeout S  how long each trial waits for the device (default 30 s)\n"
         "  --participants N  a cohort: N simulated participants PREFIX-01 .. PREFIX-N (PREFIX:\n"
         "                    --participant, default sim), one after the other, participant k\n"
         "                    with the plan's seed + k - 1; each gets its group and block order\n"
         "                    as the protocol assigns them (1 .. 1000; needs --bot)\n"
         ) + kHumanFlagsUsage + std::string(
         "  --help            print this help\n"
         "\n"
         "Exit codes: 0 the session ran to its end or to a break that ends the sitting\n"
         "(trial failures are data, not errors), 1 the data could not be written or the\n"
         "session folder is inconsistent, 2 bad input (a flag, a protocol, level or bot\n"
         "that cannot be loaded, a protocol changed since the session started, no --bot).\n");
  return text.c_str();
}

SessionOptionsResult parseSessionOptions(const std::vector<std::string>& args) {
  SessionOptionsResult result;
  SessionOptions& o = result.options;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .positional("protocol file", 1, [&](const std::string& path) { o.protocolPath = path; })
      .option("--participant", cli::text(o.participant, "a participant id"))
      .option("--session", cli::text(o.session, "a session id"))
      .option("--data", cli::text(o.dataRoot, "a directory"))
      .option("--bot", cli::text(o.botPath, "a bot file"))
      .option("--levels", cli::text(o.levelsDir, "a directory"))
      .option("--participants", cli::integerIn(o.participants, 1, 1000, "a number of participants from 1 to 1000"))
      .option("--device-profile", cli::text(o.deviceProfile, "a device profile name or file"))
      .option("--device", cli::text(o.device, "bot or udp"))
      .option("--port", cli::integerIn(o.port, 1, 65535, "a port from 1 to 65535"))
      .option("--client-timeout", cli::numberIn(o.clientTimeout, 0.001, 3600.0, "seconds from 0.001 to 3600"))
      // Lua integers are signed 64-bit, and the plan's trial seeds reach bots as one.
      .option("--seed", cli::unsignedUpTo(o.seed, 0x7fffffffffffffffULL, "a whole number from 0 to 9223372036854775807"));
  std::string humanDevice;  // --human-device: what the human model's hand holds
  addHumanFlags(reader, o.human, humanDevice);
  result.error = reader.read(args);
  if (!result.error.empty() || o.help) return result;
  result.error = checkHumanFlags(o.human, humanDevice);
  if (!result.error.empty()) return result;
  if (o.protocolPath.empty()) result.error = "missing the protocol file";
  else if (o.participants > 0 && !o.botPath) result.error = "--participants needs --bot: a cohort is simulated participants";
  else if (o.participants > 0 && o.participant.empty()) o.participant = "sim";
  else if (o.participant.empty()) result.error = "missing --participant ID";
  else if (o.device != "bot" && o.device != haptics::kUdpDevice) result.error = "--device needs bot or udp, not '" + o.device + "'";
  else if (o.device == haptics::kUdpDevice && o.botPath) result.error = "--device udp and --bot exclude each other: the participant plays";
  return result;
}

}  // namespace hemiroll::game
