#pragma once
// What a trial's sidecar says about it besides the samples: who, what level,
// which model, which device, how it was sampled, how it ended. The caller
// (the game's run command, a test) fills TrialMeta before the trial and
// TrialEnd after it; engine/record adds the start time, the row counts and
// the "complete" flag itself.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "engine/haptics/DeviceSpec.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/physics/ForceCoupling.h"
#include "engine/physics/HemisphereParams.h"

namespace hemiroll::record {

// Ordered key/value pairs for anything the schema does not name (condition,
// block, notes). Values are text.
using Fields = std::vector<std::pair<std::string, std::string>>;

struct TrialMeta {
  // Names the trial's files: <trialId>.csv, <trialId>.json. Letters, digits,
  // '-', '_' and '.' only (checked): it becomes a file name.
  std::string trialId = "trial-001";
  std::string participant;   // empty: the session's
  std::string session;       // empty: the session's
  std::string taskName = "hemiroll";
  std::string levelName;
  std::string levelHash;     // as the level loader computes it (opaque text here)
  std::uint64_t seed = 0;
  physics::HemisphereParams params;
  physics::CouplingDef coupling;
  haptics::GuidanceDef guidance;   // the trial's haptic guidance (kind none: no guidance); scale = its fade value
  std::string deviceName = "device";
  haptics::DeviceSpec deviceSpec;  // its name field is not used (deviceName is)
  double tickPeriod = 0.001;       // servo period [s]
  int recordEvery = 10;            // ticks per row; rate = 1 / (tickPeriod * recordEvery)
  std::string softwareVersion;     // empty: this build's version
  Fields extra;

  double samplingRate() const { return 1.0 / (tickPeriod * recordEvery); }  // [Hz]
};

struct TrialEnd {
  std::string outcome = "aborted";   // e.g. "success", "failure", "aborted", "fault"
  std::string reason;                // one sentence, may be empty
  // From ServoLoop::timingSummary(); hasTiming false for headless runs (no clock).
  bool hasTiming = false;
  haptics::LoopTimingSummary timing;
  std::uint64_t droppedRows = 0;     // ServoLoop::recordDropped()
  // How the trial's device fared (a device behind the UDP bridge: the stop
  // in words, packet counts); the sidecar's outcome.device, absent when empty.
  Fields device;
};

// This build's version (the CMake project version).
const char* softwareVersion();
// Now as ISO-8601 UTC with milliseconds, e.g. 2026-11-22T06:40:00.123Z.
std::string utcTimestamp();

}  // namespace hemiroll::record
