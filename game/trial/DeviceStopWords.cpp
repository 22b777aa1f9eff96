#include "game/trial/DeviceStopWords.h"

#include <sstream>

namespace hemiroll::game {

namespace {

std::string ms(double seconds) {
  std::ostringstream out;
  out << seconds * 1e3 << " ms";
  return out.str();
}

std::string figure(double v, const char* unit) {
  std::ostringstream out;
  out << v << " " << unit;
  return out.str();
}

// A DeviceError, which behind the bridge is one of three things.
std::string bridgeWords(const BridgeFacts& b) {
  if (b.clientGone)
    return "the device's client program has gone (no packet for " + ms(b.silentFor) +
           "): it exited, crashed or was stopped; restart it and the trial";
  if (b.deviceStatus != 0)
    return "the device reported a fault (status " + std::to_string(b.deviceStatus) +
           "): check the device itself (emergency stop, overheating, calibration, its USB or power)";
  if (b.stale)
    return "packets from the device stopped for more than " + ms(b.watchdog) +
           " (the bridge's watchdog): the client was held up or packets were lost; check the computer's load and "
           "the client's priority";
  return "the device reported an error";
}

}  // namespace

StopLimits stopLimitsOf(const haptics::SafetyDef& s) {
  StopLimits l;
  l.continuousForce = s.continuousForce;
  l.aboveContinuousLimit = s.aboveContinuousLimit;
  l.maxTickLateness = s.maxTickLateness;
  l.staleLimit = s.staleLimit;
  l.maxDeviceSpeed = s.maxDeviceSpeed;
  return l;
}

std::string deviceStopWords(haptics::SafetyFault fault, const BridgeFacts& b, const StopLimits& l) {
  using haptics::SafetyFault;
  switch (fault) {
    case SafetyFault::None: return "";
    case SafetyFault::DeviceError: return b.present ? bridgeWords(b) : "the device reported an error";
    case SafetyFault::StaleDevice:
      if (b.present && b.clientGone) return bridgeWords(b);
      return "the device's position stopped updating for more than " + ms(l.staleLimit) +
             " (stale data): the device or its client stalled";
    case SafetyFault::NonFiniteForce:
      return "the simulation produced an invalid force (not a number); the force was cut: report this with the "
             "trial's files";
    case SafetyFault::VelocityGuard:
      return "the handle moved faster than " + figure(l.maxDeviceSpeed, "m/s") +
             " (the speed guard): a flick, a dropped handle, or the client's velocity in the wrong units";
    case SafetyFault::PositionJump:
      return "the handle's position jumped faster than " + figure(l.maxDeviceSpeed, "m/s") +
             ": check the client's position units (metres) and the device's calibration";
    case SafetyFault::EnergyInjection:
      return "the simulation gained energy the hand did not put in (an unstable coupling); the force was cut";
    case SafetyFault::RunawayRotation:
      return "the hemisphere spun faster than the guard allows (an unstable coupling); the force was cut";
    case SafetyFault::ModelHalted:
      return "the hemisphere left the model's range (tipped over or the point ran off its face)";
    case SafetyFault::LoopOverrun:
      return "hemiroll's 1 kHz servo loop was held up for more than " + ms(l.maxTickLateness) +
             ": the computer is overloaded; close other programs";
    case SafetyFault::OutsideWorkspace:
      return "the handle was reported outside the device's workspace: check the client's units (metres) and "
             "origin, and the device profile";
    case SafetyFault::ForceSaturated:
      return "the force stayed above the device's continuous rating of " + figure(l.continuousForce, "N") +
             " for more than " + figure(l.aboveContinuousLimit, "s") +
             ", which would overheat its motors: use a softer coupling or a stronger device";
  }
  return haptics::safetyFaultName(fault);
}

std::string packetCountWords(const haptics::UdpBridgeCounters& c) {
  std::ostringstream out;
  out << c.accepted << " device states received, " << c.lost << " lost, " << c.outOfOrder << " out of order, "
      << c.late << " late, " << c.malformed << " malformed";
  return out.str();
}

}  // namespace hemiroll::game
