#pragma once
// What `hemiroll analyze --out DIR` writes, built in memory first (so a bad
// input leaves nothing behind) and then written file by file, each one
// atomically (engine/record's writeFileAtomically: a reader sees the whole
// file or none).

#include <string>
#include <utility>
#include <vector>

#include "game/research/analysis/FeatureTable.h"

namespace hemiroll::game {

using OutputFiles = std::vector<std::pair<std::string, std::string>>;  // file name in DIR, content

// Per trial <id>.analysis.json and, with plots, <id>.overview.svg,
// .contact.svg, .mass_point.svg, .psi.svg, .channels.svg; then analysis.csv
// and analysis.md over all trials.
OutputFiles analysisFiles(const std::vector<AnalysedTrial>& trials, bool plots);

// Creates dir if needed. Throws record::RecordError naming the file or folder.
void writeOutputFiles(const std::string& dir, const OutputFiles& files);

}  // namespace hemiroll::game
