#pragma once
// `hemiroll play [LEVEL.lua] [flags]` (and `hemiroll` with no arguments):
// opens the game window on the title screen, or straight into LEVEL.
//   --levels DIR        the level select lists DIR/*.lua (default: the
//                       shipped levels, found as the assets are:
//                       game/ui/view/ShippedDirectories.h)
//   --size WxH          window size [px] (default 1280x720)
//   --no-vsync          no vsync (the frame cap still holds)
//   --autoplay SECONDS  a scripted mouse takes hold of the mass point and
//                       circles it for at most SECONDS of wall time (or
//                       --watch: the autopilot plays), until the trial ends
//                       or a safety stop; then the program prints the frame
//                       rate, the CPU it used, the servo loop's timing and
//                       stalls, the safety stops and the trial's outcome,
//                       and exits (LEVEL required)
// LEVEL is found as given, else under the levels folder by its file name.
//   --tour DIR          title -> level select -> play -> pause -> results
//                       driven by synthetic input, one PNG per screen in DIR
// Exit codes: 0 done, 2 bad flags or no display (one message saying how to
// run headless instead).

#include <string>
#include <vector>

namespace hemiroll::game {

struct PlayOptions {
  std::string level;             // "" = the title screen
  std::string levelsDir;         // "" = the shipped levels (findLevelsDirectory)
  int width = 1280, height = 720;
  bool vsync = true;
  double autoplay = 0.0;         // [s]; 0 = a human plays
  bool watch = false;            // --watch: the autopilot plays LEVEL (the player may take over)
  std::string tourDir;           // --tour: screenshots of the main screens go here
  std::string deviceProfile;     // --device-profile: the UDP device's limits (devices/NAME.lua)
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
