#include "game/commands/VersionCommand.h"

#include <iostream>

#include "game/commands/ExitCode.h"

#ifndef HEMIROLL_VERSION
#error "HEMIROLL_VERSION must be defined by the build (game/CMakeLists.txt)"
#endif

namespace hemiroll::game {

int runVersionCommand(const std::vector<std::string>& args) {
  if (!args.empty() && args.front() != "--help" && args.front() != "-h") {
    std::cerr << "hemiroll version: unexpected argument '" << args.front() << "'\nusage: hemiroll version\n";
    return kExitUsage;
  }
  std::cout << "hemiroll " << HEMIROLL_VERSION << "\n";
  return kExitOk;
}

}  // namespace hemiroll::game
