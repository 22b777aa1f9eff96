#pragma once
// `hemiroll check FILE... [--as level|protocol|scenario|sweep]`: loads each
// file as the command that would use it does and reports every problem it
// can find without playing it (issue 30): a load error (file and line), and
// for a loaded level what only shows once a trial starts: a coupling the
// device cannot render, a stage the autopilot can show is out of reach (a
// contact point beyond the device, a rest the bands rule out), a hold
// longer than the time limit, a score function that fails on a summary.
// A protocol is checked with every condition's level under its overrides.
// Exit 0 when every file is clean, 2 when any has a problem.

#include <string>
#include <vector>

namespace hemiroll::game {

// What kind of file a path holds (--as, else guessed from its text).
enum class CheckedKind { Level, Protocol, Scenario, Sweep };

// The guess: a table with `blocks` is a protocol; one with `drive` and
// `axes` a sweep spec; one with `drive` and `duration` a scenario; anything
// else a level.
CheckedKind guessKind(const std::string& source);

// The problems of one file (empty: clean), each a sentence naming where.
std::vector<std::string> checkFile(const std::string& path, CheckedKind kind);

int runCheckCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
