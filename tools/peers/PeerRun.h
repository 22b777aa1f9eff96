#pragma once
// One run of one scene by one engine at one setting, and how it is scored
// against hemiroll's reference. Owns: the run record, the comparison, CPU
// timing. Must not know any engine's API.

#include <algorithm>
#include <string>
#include <vector>

#include "tools/peers/PeerScene.h"

namespace hemiroll::tools::peers {

struct RunResult {
  std::string engine;   // "hemiroll", "mujoco", "bullet", "ode"
  std::string setting;  // e.g. "rk4", "tuned"
  double step = 0.0;    // time step [s], or the tolerance for an adaptive method
  bool adaptive = false;
  std::vector<Sample> samples;  // every kSampleInterval from 0 to the horizon
  double cpuSeconds = 0.0;      // median over repeats
  std::string failure;          // non-empty: the engine refused or blew up (no samples)
};

struct RunScore {
  double contactError = 0.0;   // max over samples of |contact - reference| [m]
  double contactErrorFirstSecond = 0.0;  // the same over t <= 1 s [m]
  double tiltError = 0.0;      // max |tilt - reference| [rad]
  double maxSlip = 0.0;        // max slip speed [m/s]
  double maxPenetration = 0.0; // [m]
  double energyDrift = 0.0;    // max |E(t) - E(0)| [J], conservative scenes
  double trackingError = 0.0;  // prescribed scenes: max |p - p(t)| of the point on the face [m]
  double cpuPerSimSecond = 0.0;
  bool finite = true;          // every sample finite and the run complete
};

RunScore score(const PeerScene& scene, const RunResult& run, const std::vector<Sample>& reference);

double cpuNow();  // this thread's CPU time [s]

// Runs `once` (which returns a RunResult with the CPU time of its stepping
// alone in cpuSeconds: building a model, parsing XML, is not the engine's cost
// per simulated second) until about `targetSeconds` of stepping have been
// spent, 1 to `maxRepeats` times, and keeps the median time.
template <class Once>
RunResult timedRun(const Once& once, double targetSeconds, int maxRepeats) {
  RunResult result = once();
  std::vector<double> times{result.cpuSeconds};
  double spent = result.cpuSeconds;
  while (static_cast<int>(times.size()) < maxRepeats && spent < targetSeconds && result.failure.empty()) {
    const double t = once().cpuSeconds;
    times.push_back(t);
    spent += t;
  }
  std::sort(times.begin(), times.end());
  result.cpuSeconds = times[times.size() / 2];
  return result;
}

}  // namespace hemiroll::tools::peers
