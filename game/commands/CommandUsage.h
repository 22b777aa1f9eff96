#pragma once
// What every command does with its parsed flags before it runs: a mistake is
// one sentence and the usage on stderr (exit 2), --help the usage on stdout
// (exit 0). `Parsed` is a command's <Name>OptionsResult: `error` ("" when the
// flags are good) and `options` with a `help` switch.

#include <iostream>
#include <optional>
#include <string>

#include "game/commands/ExitCode.h"

namespace hemiroll::game {

// The exit code when the command has nothing to run, else nullopt.
template <class Parsed>
std::optional<int> exitBeforeRunning(const std::string& prefix, const Parsed& parsed, const std::string& usage) {
  if (!parsed.error.empty()) {
    std::cerr << prefix << parsed.error << "\n\n" << usage;
    return kExitUsage;
  }
  if (parsed.options.help) {
    std::cout << usage;
    return kExitOk;
  }
  return std::nullopt;
}

}  // namespace hemiroll::game
