// hemiroll-window: the commands that open a window (play, screenshot), run
// by `hemiroll play` and `hemiroll screenshot` in their own place
// (game/commands/WindowProgram.h); started alone it takes the same
// arguments, and no command means play.

#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "game/commands/ExitCode.h"
#include "game/commands/PlayCommand.h"
#include "game/commands/ScreenshotCommand.h"
#include "game/commands/WindowProgram.h"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return hemiroll::game::runCommandGuarded("play", hemiroll::game::runPlayCommand, {});
  const std::string& command = args.front();
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "play") return hemiroll::game::runCommandGuarded(command, hemiroll::game::runPlayCommand, rest);
  if (command == "screenshot")
    return hemiroll::game::runCommandGuarded(command, hemiroll::game::runScreenshotCommand, rest);
  std::cerr << hemiroll::game::kWindowProgramName << ": unknown command '" << command
            << "': this program runs the commands that open a window (play, screenshot); the others are "
               "hemiroll's (hemiroll --help)\n";
  return hemiroll::game::kExitUsage;
}
