#pragma once
// Exit codes of every hemiroll command (docs/SCENARIOS.md, "Exit codes").

namespace hemiroll::game {

enum ExitCode : int {
  kExitOk = 0,       // done; a domain event (tip-over, off-face) is a result, not a failure
  kExitFailure = 1,  // the environment failed: an output file could not be written
  kExitUsage = 2,    // the input is wrong: unknown flag, bad value, bad scenario
};

}  // namespace hemiroll::game
