#pragma once
// The command line every SDK client shares (hemiroll-touch-client,
// hemiroll-omega-client, hemiroll-falcon-client): where the bridge is, the
// force limit, how long; the run and its summary. Exit codes: 0 ran, 1 the
// device or the bridge could not be used (the reason on stderr), 2 a bad
// command line.

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "tools/sdkclients/ClientRun.h"
#include "tools/sdkclients/DeviceDriver.h"

namespace hemiroll::sdkclients {

struct ClientCommand {
  std::string program;             // e.g. "hemiroll-touch-client"
  std::string device;              // e.g. "a 3D Systems Touch or Touch X (OpenHaptics)"
  double defaultMaxForce = 3.0;    // [N] when --max-force is not given and the SDK does not say
  // Extra options of this client (e.g. --falcon-firmware): name, value help, what it sets.
  struct Extra {
    std::string name, value, help;
    std::string* target;
  };
  std::vector<Extra> extras;
};

struct ParsedClientLine {
  ClientRunDef run;
  bool help = false;
  std::string error;
};

ParsedClientLine parseClientLine(const ClientCommand& command, const std::vector<std::string>& args);
std::string clientLineUsage(const ClientCommand& command);
void printRunSummary(const ClientRunResult& r, std::ostream& out);

// Parses, runs `makeDriver()`'s device until SIGINT/SIGTERM or --duration, prints the summary.
int clientMain(const ClientCommand& command, int argc, char** argv,
               const std::function<std::unique_ptr<DeviceDriver>()>& makeDriver);

}  // namespace hemiroll::sdkclients
