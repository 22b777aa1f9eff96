#pragma once
// A trial's features as JSON (nlohmann-json): SI keys with unit suffixes,
// as engine/record writes them. A feature not found carries "found": false
// and its "reason" instead of numbers, so no reader mistakes a 0 for a
// measurement. Keys: docs/ANALYSIS.md.

#include <string>

#include "engine/analysis/GuidanceWork.h"
#include "engine/analysis/TrialAnalyzer.h"
#include "game/research/analysis/TrialData.h"

namespace hemiroll::game {

// Pretty-printed, with a final newline.
// `guidance`: written as "guidance" when present (a guided recording).
std::string featuresJson(const TrialData& trial, const analysis::TrialFeatures& features,
                         const analysis::GuidanceWork& guidance = {});

}  // namespace hemiroll::game
