#include "tools/hapticclient/ClientOptions.h"

#include <limits>

#include "game/cli/ArgumentReader.h"

namespace hemiroll::hapticclient {

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
         "  --centre X,Y,Z          where the hand starts and its circle begins [m] (default 0,0,0.04:\n"
         "                          the mass point of a 4 cm hemisphere upright, where the coupling engages)\n"
         "  --circle-radius M       radius of the hand's intended circle (default 0: hold still)\n"
         "  --circle-frequency HZ   turns per second of that circle (default 0.5)\n"
         "  --realtime-priority N   ask for SCHED_FIFO at N (1..99) so that other work cannot\n"
         "                          starve the 1 kHz sends (default 0: normal scheduler)\n"
         "A simulated physical device (docs/UDP_BRIDGE.md; give it your profile's figures):\n"
         "  --peak-force N          clamp every force to N (the motors' limit; default: none)\n"
         "  --handle-mass KG        the handle's moving mass, added to the hand's (default 0)\n"
         "  --friction N            the handle's Coulomb friction (default 0)\n"
         "  --resolution M          position quantisation, one encoder count (default: none)\n"
         "  --passive               a passive hand: no stiffness or damping towards an intent\n"
         "Faults, to try hemiroll's stops:\n"
         "  --jitter S              delay each state by a uniform 0..S seconds (default 0)\n"
         "  --loss P                lose each state with probability P (default 0)\n"
         "  --reorder P             send a state after the next one with probability P (default 0)\n"
         "  --seed N                the faults' random seed (default 1)\n"
         "  --pause-at S --pause-for S  send nothing for a while (the bridge's watchdog)\n"
         "  --exit-at S             stop for good at S (the client is gone)\n"
         "  --fault-at S            report a device fault (status 1) from S on\n"
         "  --step M                a square wave of M on x every --step-period S/2 (default\n"
         "                          0.2 s); the summary gives the step-to-force latency\n"
         "  --help                  this text\n";
}

ParsedOptions parseClientOptions(const std::vector<std::string>& args) {
  ParsedOptions p;
  ClientOptions& o = p.options;
  constexpr double kHuge = std::numeric_limits<double>::max();
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .option("--host", cli::text(o.host, "an address"))
      .option("--port",
              [&](const std::string& flag, const std::string& value) {
                long long port = 0;
                if (!cli::readInteger(value, port) || port < 1 || port > 65535)
                  return cli::needs(flag, "an integer port in 1..65535", value);
                o.port = static_cast<std::uint16_t>(port);
                return std::string();
              })
      .option("--duration", cli::numberIn(o.duration, std::numeric_limits<double>::denorm_min(), 1e6, "a positive number of seconds, at most 1e6"))
      .option("--rate", cli::numberIn(o.rate, 1.0, 10000.0, "a rate in 1..10000 Hz"))
      .option("--hand-mass", cli::positiveNumber(o.hand.mass, "a positive mass in kg"))
      .option("--hand-stiffness", cli::numberIn(o.hand.stiffness, 0.0, kHuge, "a stiffness >= 0 in N/m"))
      .option("--hand-damping", cli::numberIn(o.hand.damping, 0.0, kHuge, "a damping >= 0 in N s/m"))
      .option("--centre",
              [&](const std::string& flag, const std::string& value) {
                if (!cli::readNumbers(value, o.centre)) return cli::needs(flag, "three numbers x,y,z in metres", value);
                return std::string();
              })
      .option("--circle-radius", cli::numberIn(o.circleRadius, 0.0, kHuge, "a radius >= 0 in metres"))
      .option("--circle-frequency", cli::numberIn(o.circleFrequency, 0.0, kHuge, "a frequency >= 0 in Hz"))
      .option("--realtime-priority", cli::integerIn(o.realtimePriority, 0, 99, "an integer priority in 0..99"))
      .option("--peak-force", cli::numberIn(o.peakForce, 0.0, kHuge, "a force >= 0 in N"))
      .option("--handle-mass", cli::numberIn(o.handleMass, 0.0, kHuge, "a mass >= 0 in kg"))
      .option("--friction", cli::numberIn(o.friction, 0.0, kHuge, "a force >= 0 in N"))
      .option("--resolution", cli::numberIn(o.resolution, 0.0, 1.0, "a length in 0..1 m"))
      .flag("--passive", [&] { o.hand.stiffness = 0.0; o.hand.damping = 0.0; })
      .option("--jitter", cli::numberIn(o.jitter, 0.0, 1.0, "seconds in 0..1"))
      .option("--loss", cli::numberIn(o.loss, 0.0, 1.0, "a probability in 0..1"))
      .option("--reorder", cli::numberIn(o.reorder, 0.0, 1.0, "a probability in 0..1"))
      .option("--seed", cli::unsignedUpTo(o.seed, ~std::uint64_t{0}, "a whole number"))
      .option("--pause-at", cli::numberIn(o.pauseAt, 0.0, 1e6, "seconds >= 0"))
      .option("--pause-for", cli::numberIn(o.pauseFor, 0.0, 1e6, "seconds >= 0"))
      .option("--exit-at", cli::numberIn(o.exitAt, 0.0, 1e6, "seconds >= 0"))
      .option("--fault-at", cli::numberIn(o.faultAt, 0.0, 1e6, "seconds >= 0"))
      .option("--step", cli::numberIn(o.step, 0.0, 0.1, "a length in 0..0.1 m"))
      .option("--step-period", cli::numberIn(o.stepPeriod, 0.002, 1e3, "seconds from 0.002"));
  p.error = reader.read(args);
  return p;
}

}  // namespace hemiroll::hapticclient
