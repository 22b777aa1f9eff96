#pragma once
// `hemiroll play [LEVEL.lua] [flags]` (and `hemiroll` with no arguments):
// opens the game window on the title screen, or straight into LEVEL.
//   --levels DIR        the level select lists DIR/*.lua (default: levels)
//   --size WxH          window size [px] (default 1280x720)
//   --no-vsync          frames as fast as they come (measuring)
//   --autoplay SECONDS  a scripted mouse takes hold of the mass point and
//                       circles it for SECONDS of wall time, then the
//                       program prints the median frame rate and the servo
//                       loop's timing and exits (LEVEL required)
//   --tour DIR          title -> level select -> play -> pause -> results
//                       driven by synthetic input, one PNG per screen in DIR
// Exit codes: 0 done, 2 bad flags or no display (one message saying how to
// run headless instead).

#include <string>
#include <vector>

namespace hemiroll::game {

struct PlayOptions {
  std::string level;             // "" = the title screen
  std::string levelsDir = "levels";
  int width = 1280, height = 720;
  bool vsync = true;
  double autoplay = 0.0;         // [s]; 0 = a human plays
  bool watch = false;            // --watch: the autopilot plays LEVEL (the player may take over)
  std::string tourDir;           // --tour: screenshots of the main screens go here
  bool help = false;
};

struct PlayOptionsResult {
  PlayOptions options;
  std::string error;  // "" = parsed
};

PlayOptionsResult parsePlayOptions(const std::vector<std::string>& args);
std::string playUsage();
// The message `hemiroll play` gives without a display (public for tests).
std::string playNoDisplayMessage(const std::string& why);
int runPlayCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
