#pragma once
// One trial's samples as `hemiroll analyze` reads them, whatever the file:
// plain SI columns, which the analysis takes as spans.

#include <string>
#include <vector>

#include "engine/analysis/TrialAnalyzer.h"

namespace hemiroll::game {

struct TrialData {
  std::string id;                  // unique within one invocation; names the output files
  std::string source;              // the file read
  std::string kind;                // "recording" (trial CSV + sidecar) or "sim" (`hemiroll sim` CSV)
  std::vector<std::string> notes;  // what the reader had to say (an interrupted recording, ...)
  std::vector<double> time, massX, massY, contactX, contactY, psi;  // [s], [m], [rad]
  std::vector<double> proxyX, proxyY;  // the proxy on the plane [m]; recordings only (empty for sim CSVs)

  analysis::TrialSamples samples() const { return {time, massX, massY, contactX, contactY, psi}; }
};

}  // namespace hemiroll::game
