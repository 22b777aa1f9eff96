#include "game/commands/RunOptions.h"

#include <cerrno>
#include <cstdlib>

namespace hemiroll::game {

namespace {

// Decimal digits only, at most 2^63 - 1 (Lua integers are signed 64-bit, and
// the bot receives the seed as one).
bool parseSeed(const std::string& text, std::uint64_t& value) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (errno != 0 || end != text.c_str() + text.size() || v > 0x7fffffffffffffffULL) return false;
  value = v;
  return true;
}

}  // namespace

const char* runUsage() {
  return "usage: hemiroll run LEVEL.lua --bot BOT.lua [--seed N] [--record DIR] [--realtime]\n"
         "\n"
         "Plays a level with a bot (a Lua module, e.g. scripts/bots/rose.lua) and prints one\n"
         "JSON line: level, bot, outcome, reason, time, score, medal, ticks, wall_time\n"
         "(docs/RUN.md). Headless and as fast as the CPU allows unless --realtime;\n"
         "the same level, bot and seed give the same result bit for bit.\n"
         "\n"
         "  --bot BOT.lua   the bot that plays (required)\n"
         "  --seed N        seed of the level's and the bot's hemiroll.random and the\n"
         "                  bot's init (0 .. 9223372036854775807; default 0)\n"
         "  --record DIR    record the trial into DIR (per-trial CSV + JSON sidecar and\n"
         "                  results.csv, docs/RECORDING.md)\n"
         "  --realtime      pace the servo ticks at 1 kHz on the wall clock\n"
         "  --help          print this help\n"
         "\n"
         "Exit codes: 0 success, 1 failure (the trial failed, or the recording could not\n"
         "be written), 2 bad input (a flag, or a level or bot that cannot be loaded).\n";
}

RunOptionsResult parseRunOptions(const std::vector<std::string>& args) {
  RunOptionsResult result;
  RunOptions& o = result.options;
  auto fail = [&](const std::string& message) {
    result.error = message;
    return result;
  };

  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i];
    if (arg == "--help" || arg == "-h") {
      o.help = true;
      continue;
    }
    if (arg == "--realtime") {
      o.realtime = true;
      continue;
    }
    if (arg.rfind("-", 0) != 0 || arg == "-") {
      if (!o.levelPath.empty()) return fail("unexpected argument '" + arg + "' (only one level file)");
      o.levelPath = arg;
      continue;
    }
    std::optional<std::string> inlineValue;
    if (const auto eq = arg.find('='); eq != std::string::npos) {
      inlineValue = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
    }
    if (arg != "--bot" && arg != "--seed" && arg != "--record") return fail("unknown flag '" + arg + "'");
    std::string value;
    if (inlineValue) {
      value = *inlineValue;
    } else {
      if (i + 1 >= args.size()) return fail("flag " + arg + " needs a value");
      value = args[++i];
    }
    if (arg == "--seed") {
      if (!parseSeed(value, o.seed))
        return fail("flag --seed needs a whole number from 0 to 9223372036854775807, got '" + value + "'");
    } else if (value.empty()) {
      return fail("flag " + arg + " needs a " + (arg == "--bot" ? "bot file" : "directory"));
    } else if (arg == "--bot") {
      o.botPath = value;
    } else {
      o.recordDir = value;
    }
  }
  if (o.help) return result;
  if (o.levelPath.empty()) return fail("missing the level file");
  if (o.botPath.empty()) return fail("missing --bot BOT.lua");
  return result;
}

}  // namespace hemiroll::game
