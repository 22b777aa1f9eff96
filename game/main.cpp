// hemiroll: the command-line entry point. Each subcommand lives in
// game/commands/<Name>Command.{h,cpp}; this file only dispatches. The
// commands that open a window run in hemiroll-window (WindowProgram.h): this
// program links no window library.

#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "game/commands/AnalyzeCommand.h"
#include "game/commands/BidsCommand.h"
#include "game/commands/CheckCommand.h"
#include "game/commands/ExitCode.h"
#include "game/commands/FiguresCommand.h"
#include "game/commands/RunCommand.h"
#include "game/commands/SessionCommand.h"
#include "game/commands/SimCommand.h"
#include "game/commands/SweepCommand.h"
#include "game/commands/VersionCommand.h"
#include "game/commands/WindowProgram.h"

namespace {

struct CommandEntry {
  std::string_view name;
  std::string_view summary;
  int (*run)(const std::vector<std::string>& args);  // null: the command runs in hemiroll-window
};

constexpr CommandEntry kCommands[] = {
    {"play", "open the game window (the default with no command)", nullptr},
    {"sim", "run a scenario's physics headless and write the trajectory as CSV", hemiroll::game::runSimCommand},
    {"run", "play a level with a bot (headless) and print the result as one JSON line", hemiroll::game::runRunCommand},
    {"session", "run a research protocol for a participant (bots headless; people in the window)",
     hemiroll::game::runSessionCommand},
    {"screenshot", "render one frame of a level offscreen and write it as a PNG", nullptr},
    {"analyze", "measure phases, rose and helix in recorded trials; tables and SVG plots", hemiroll::game::runAnalyzeCommand},
    {"figures", "regenerate the paper's Figs. 9-11 from the simulator, with their features", hemiroll::game::runFiguresCommand},
    {"sweep", "sweep the rose drive over a grid of parameters; shards, merge, heatmaps", hemiroll::game::runSweepCommand},
    {"bids", "write session folders as a BIDS motion dataset", hemiroll::game::runBidsCommand},
    {"check", "load levels, protocols, scenarios or sweep specs and report every problem found", hemiroll::game::runCheckCommand},
    {"version", "print the version", hemiroll::game::runVersionCommand},
};

void printUsage(std::ostream& out) {
  out << "usage: hemiroll COMMAND [ARGS...]\n"
         "       hemiroll --help | hemiroll COMMAND --help\n"
         "\ncommands:\n";
  for (const CommandEntry& c : kCommands) out << "  " << c.name << std::string(12 - c.name.size(), ' ') << c.summary << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  // No command: the game, as a player who double-clicks the program expects.
  if (args.empty()) return hemiroll::game::execWindowProgram(argv[0], "play", {});
  const std::string& command = args.front();
  if (command == "--help" || command == "-h" || command == "help") {
    printUsage(std::cout);
    return hemiroll::game::kExitOk;
  }
  if (command == "--version") return hemiroll::game::runVersionCommand({});
  for (const CommandEntry& c : kCommands) {
    if (c.name != command) continue;
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (c.run == nullptr) return hemiroll::game::execWindowProgram(argv[0], command, rest);
    // Each command reports what it expects to go wrong itself.
    return hemiroll::game::runCommandGuarded(command, c.run, rest);
  }
  std::cerr << "hemiroll: unknown command '" << command << "'\n\n";
  printUsage(std::cerr);
  return hemiroll::game::kExitUsage;
}
