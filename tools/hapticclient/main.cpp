// hemiroll-haptic-client: the UDP bridge's reference client (HapticClient.h).
// Exit codes: 0 ran, 1 could not run (socket), 2 bad command line,
// 3 ran but no force ever came back (no bridge listening?).

#include <atomic>
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "tools/hapticclient/ClientOptions.h"
#include "tools/hapticclient/HapticClient.h"

namespace {
std::atomic<bool> gStop{false};
extern "C" void onSignal(int) { gStop.store(true); }
}  // namespace

int main(int argc, char** argv) {
  using namespace hemiroll::hapticclient;
  const ParsedOptions parsed = parseClientOptions(std::vector<std::string>(argv + 1, argv + argc));
  if (!parsed.error.empty()) {
    std::cerr << "hemiroll-haptic-client: " << parsed.error << "\n" << clientUsage();
    return 2;
  }
  if (parsed.options.help) {
    std::cout << clientUsage();
    return 0;
  }
  // SIGINT/SIGTERM end the run early but still print the summary.
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  const ClientSummary s = runClient(parsed.options, gStop);
  if (!s.error.empty()) {
    std::cerr << "hemiroll-haptic-client: " << s.error << "\n";
    return 1;
  }
  printSummary(s, std::cout);
  if (s.forcesReceived == 0) {
    std::cerr << "hemiroll-haptic-client: no force came back from " << parsed.options.host << ":"
              << parsed.options.port << "; is hemiroll's UDP bridge listening there?\n";
    return 3;
  }
  return 0;
}
