#include "tools/hapticclient/ClientOptions.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace hemiroll::hapticclient {

namespace {

bool toDouble(const std::string& text, double& out) {
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(out);
}

// "x,y,z" in metres.
bool toTriple(const std::string& text, std::array<double, 3>& out) {
  std::stringstream s(text);
  std::string part;
  for (int i = 0; i < 3; ++i) {
    if (!std::getline(s, part, ',') || !toDouble(part, out[static_cast<std::size_t>(i)])) return false;
  }
  return !std::getline(s, part, ',');
}

}  // namespace

const char* clientUsage() {
  return "usage: hemiroll-haptic-client [options]\n"
         "Emulates a haptic device (a spring-mass hand) for hemiroll's UDP bridge: sends the\n"
         "device state at --rate, applies the force that comes back, and prints a summary\n"
         "(packets, lost, out of order, round-trip times) when it ends.\n"
         "  --host ADDR             bridge address (default 127.0.0.1)\n"
         "  --port N                bridge port (default 47110)\n"
         "  --duration S            seconds to run (default 5; SIGINT/SIGTERM end it early)\n"
         "  --rate HZ               states per second (default 1000)\n"
         "  --hand-mass KG          hand and device mass (default 0.3)\n"
         "  --hand-stiffness N/M    grip and arm stiffness (default 300)\n"
         "  --hand-damping NS/M     grip and arm damping (default 15)\n"
         "  --centre X,Y,Z          where the hand starts and its circle begins [m] (default 0,0,0)\n"
         "  --circle-radius M       radius of the hand's intended circle (default 0: hold still)\n"
         "  --circle-frequency HZ   turns per second of that circle (default 0.5)\n"
         "  --realtime-priority N   ask for SCHED_FIFO at N (1..99) so that other work cannot\n"
         "                          starve the 1 kHz sends (default 0: normal scheduler)\n"
         "  --help                  this text\n";
}

ParsedOptions parseClientOptions(const std::vector<std::string>& args) {
  ParsedOptions p;
  ClientOptions& o = p.options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--help" || flag == "-h") {
      o.help = true;
      continue;
    }
    if (i + 1 >= args.size()) {
      p.error = flag.rfind("--", 0) == 0 ? flag + " needs a value" : "unexpected argument '" + flag + "'";
      return p;
    }
    const std::string& value = args[++i];
    double x = 0.0;
    const bool number = toDouble(value, x);
    auto bad = [&](const char* what) {
      p.error = flag + " needs " + what + ", got '" + value + "'";
      return p;
    };
    if (flag == "--host") {
      o.host = value;
    } else if (flag == "--port") {
      if (!number || x < 1 || x > 65535 || x != std::floor(x)) return bad("an integer port in 1..65535");
      o.port = static_cast<std::uint16_t>(x);
    } else if (flag == "--duration") {
      if (!number || !(x > 0.0 && x <= 1e6)) return bad("a positive number of seconds, at most 1e6");
      o.duration = x;
    } else if (flag == "--rate") {
      if (!number || !(x >= 1.0 && x <= 10000.0)) return bad("a rate in 1..10000 Hz");
      o.rate = x;
    } else if (flag == "--hand-mass") {
      if (!number || !(x > 0.0)) return bad("a positive mass in kg");
      o.hand.mass = x;
    } else if (flag == "--hand-stiffness") {
      if (!number || !(x >= 0.0)) return bad("a stiffness >= 0 in N/m");
      o.hand.stiffness = x;
    } else if (flag == "--hand-damping") {
      if (!number || !(x >= 0.0)) return bad("a damping >= 0 in N s/m");
      o.hand.damping = x;
    } else if (flag == "--centre") {
      if (!toTriple(value, o.centre)) return bad("three numbers x,y,z in metres");
    } else if (flag == "--circle-radius") {
      if (!number || !(x >= 0.0)) return bad("a radius >= 0 in metres");
      o.circleRadius = x;
    } else if (flag == "--circle-frequency") {
      if (!number || !(x >= 0.0)) return bad("a frequency >= 0 in Hz");
      o.circleFrequency = x;
    } else if (flag == "--realtime-priority") {
      if (!number || x < 0 || x > 99 || x != std::floor(x)) return bad("an integer priority in 0..99");
      o.realtimePriority = static_cast<int>(x);
    } else {
      p.error = "unknown option '" + flag + "' (see --help)";
      return p;
    }
  }
  return p;
}

}  // namespace hemiroll::hapticclient
