#include "tools/peers/PeerRun.h"

#include <time.h>

#include <algorithm>
#include <cmath>

namespace hemiroll::tools::peers {

double cpuNow() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

RunScore score(const PeerScene& scene, const RunResult& run, const std::vector<Sample>& reference) {
  RunScore s;
  s.cpuPerSimSecond = run.cpuSeconds / scene.horizon;
  if (!run.failure.empty() || run.samples.size() != reference.size()) {
    s.finite = false;
    return s;
  }
  const double e0 = run.samples.front().energy;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const Sample& a = run.samples[i];
    const Sample& r = reference[i];
    const double contact = (a.contact - r.contact).norm();
    if (!std::isfinite(contact) || !std::isfinite(a.tilt) || !std::isfinite(a.energy)) {
      s.finite = false;
      return s;
    }
    s.contactError = std::max(s.contactError, contact);
    if (a.t <= 1.0 + 1e-9) s.contactErrorFirstSecond = std::max(s.contactErrorFirstSecond, contact);
    s.tiltError = std::max(s.tiltError, std::abs(a.tilt - r.tilt));
    s.maxSlip = std::max(s.maxSlip, a.slip);
    s.maxPenetration = std::max(s.maxPenetration, a.penetration);
    if (scene.conservative) s.energyDrift = std::max(s.energyDrift, std::abs(a.energy - e0));
    if (scene.drive == PointDrive::Prescribed)
      s.trackingError = std::max(s.trackingError, (a.p - scene.trajectory->at(a.t).p).norm());
  }
  return s;
}

}  // namespace hemiroll::tools::peers
