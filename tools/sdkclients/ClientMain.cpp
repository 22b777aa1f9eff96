#include "tools/sdkclients/ClientMain.h"

#include <atomic>
#include <csignal>
#include <iostream>

#include "game/cli/ArgumentReader.h"

namespace hemiroll::sdkclients {

namespace {
std::atomic<bool> gStop{false};
extern "C" void onStopSignal(int) { gStop.store(true); }
}  // namespace

std::string clientLineUsage(const ClientCommand& c) {
  std::string text = "usage: " + c.program + " [--host ADDRESS] [--port N] [--max-force NEWTONS] [--duration SECONDS]";
  for (const auto& e : c.extras) text += " [" + e.name + " " + e.value + "]";
  text += "\n\nConnects " + c.device +
          " to hemiroll's UDP bridge (docs/UDP_BRIDGE.md):\nthe device's position out at 1 kHz, the bridge's force back.\n\n"
          "  --host ADDRESS       the bridge's IPv4 address (default 127.0.0.1)\n"
          "  --port N             the bridge's port (default 47110)\n"
          "  --max-force NEWTONS  the largest force sent to the device (default: the lower of\n"
          "                       the SDK's continuous force and " + std::to_string(c.defaultMaxForce).substr(0, 4) +
          " N); use your device profile's\n"
          "  --duration SECONDS   stop after this long (default: until Ctrl-C or the bridge closes)\n";
  for (const auto& e : c.extras) text += "  " + e.name + " " + e.value + "  " + e.help + "\n";
  return text;
}

ParsedClientLine parseClientLine(const ClientCommand& c, const std::vector<std::string>& args) {
  ParsedClientLine p;
  p.run.link.maxForce = c.defaultMaxForce;
  long long port = p.run.link.port;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { p.help = true; }).flag("-h", [&] { p.help = true; });
  reader.option("--host", [&](const std::string&, const std::string& v) {
    p.run.link.host = v;
    return std::string();
  });
  reader.option("--port", cli::integerIn(port, 1, 65535, "a port from 1 to 65535"));
  reader.option("--max-force", cli::numberIn(p.run.link.maxForce, 0.01, 50.0, "a force from 0.01 to 50 N"));
  reader.option("--duration", cli::positiveNumber(p.run.duration, "a positive number of seconds"));
  for (const auto& e : c.extras)
    reader.option(e.name, [target = e.target](const std::string&, const std::string& v) {
      *target = v;
      return std::string();
    });
  p.error = reader.read(args);
  p.run.link.port = static_cast<std::uint16_t>(port);
  return p;
}

void printRunSummary(const ClientRunResult& r, std::ostream& out) {
  const LinkCounters& c = r.counters;
  out << "force_limit_N " << r.forceLimit << "\nforces_enabled " << (r.forcesWereEnabled ? 1 : 0)
      << "\nstates_sent " << c.statesSent << "\nsends_refused " << c.sendsRefused << "\nforces_received "
      << c.forcesReceived << "\nforces_malformed " << c.forcesMalformed << "\nforces_out_of_order "
      << c.forcesOutOfOrder << "\nforces_lost " << c.forcesLost << "\nforces_clamped " << c.forcesClamped
      << "\nticks_without_force " << c.ticksWithoutForce << "\nbridge_closing " << (c.bridgeClosing ? 1 : 0)
      << "\n";
}

int clientMain(const ClientCommand& c, int argc, char** argv,
               const std::function<std::unique_ptr<DeviceDriver>()>& makeDriver) {
  const ParsedClientLine p = parseClientLine(c, std::vector<std::string>(argv + 1, argv + argc));
  if (!p.error.empty()) {
    std::cerr << c.program << ": " << p.error << "\n" << clientLineUsage(c);
    return 2;
  }
  if (p.help) {
    std::cout << clientLineUsage(c);
    return 0;
  }
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  const std::unique_ptr<DeviceDriver> driver = makeDriver();
  const ClientRunResult r = runDeviceClient(*driver, p.run, gStop);
  printRunSummary(r, std::cout);
  if (!r.error.empty()) {
    std::cerr << c.program << ": " << r.error << "\n";
    return 1;
  }
  return 0;
}

}  // namespace hemiroll::sdkclients
