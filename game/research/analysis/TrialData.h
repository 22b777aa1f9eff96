#pragma once
// One trial's samples as `hemiroll analyze` reads them, whatever the file:
// plain SI columns, which the analysis takes as spans.

#include <string>
#include <vector>

#include "engine/analysis/GuidanceWork.h"
#include "engine/analysis/TrialAnalyzer.h"

namespace hemiroll::game {

struct TrialData {
  std::string id;                  // unique within one invocation; names the output files
  std::string source;              // the file read
  std::string kind;                // "recording" (trial CSV + sidecar) or "sim" (`hemiroll sim` CSV)
  std::vector<std::string> notes;  // what the reader had to say (an interrupted recording, ...)
  std::vector<double> time, massX, massY, contactX, contactY, psi;  // [s], [m], [rad]
  std::vector<double> proxyX, proxyY;  // the proxy on the plane [m]; recordings only (empty for sim CSVs)
  // Recordings only: guidance force, proxy velocity and hand force, scene [N], [m/s].
  std::vector<double> guideX, guideY, guideZ, proxyVX, proxyVY, proxyVZ, handX, handY, handZ;

  analysis::TrialSamples samples() const { return {time, massX, massY, contactX, contactY, psi}; }
  // Empty spans for a sim CSV (no guidance there).
  analysis::GuidanceSamples guidanceSamples() const {
    const std::span<const double> t = guideX.empty() ? std::span<const double>() : std::span<const double>(time);
    return {t, guideX, guideY, guideZ, proxyVX, proxyVY, proxyVZ, handX, handY, handZ};
  }
};

}  // namespace hemiroll::game
