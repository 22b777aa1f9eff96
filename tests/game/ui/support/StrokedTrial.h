#pragma once
// A real-time mouse trial for the screens tests: the play session of a level
// with the mouse stroking side to side (amplitude [px], 4 rad/s) for a while
// of wall time, logged for replay. The replay, ghost and play-session tests
// need one; this is the one way they make it.

#include <chrono>
#include <filesystem>
#include <string>

#include "game/play/PlaySession.h"

namespace hemiroll::test {

struct StrokedTrialDef {
  std::string level;                               // the level file
  std::filesystem::path replayFile;                // where the log goes
  std::chrono::milliseconds duration{800};         // wall time played
  double amplitude = 8.0;                          // [px] of mouse motion
  bool pauseAtTheEnd = false;                      // a command in the log
};

struct StrokedTrial {
  haptics::ServoSnapshot last;  // the state the trial ended on
  std::string replayError;      // "" when the log is usable
};

StrokedTrial playStrokedTrial(const StrokedTrialDef& def);

}  // namespace hemiroll::test
