#pragma once
// The table over all trials of one `hemiroll analyze`: a CSV (SI columns
// with unit suffixes, empty where a feature was not found) and a markdown
// table for people (cm, the features found, "-" otherwise).

#include <string>
#include <vector>

#include "engine/analysis/TrialAnalyzer.h"
#include "game/analysis/TrialData.h"

namespace hemiroll::game {

struct AnalysedTrial {
  TrialData data;
  analysis::TrialFeatures features;
  analysis::GuidanceWork guidance;
};

std::string featureTableCsv(const std::vector<AnalysedTrial>& trials);
std::string featureTableMarkdown(const std::vector<AnalysedTrial>& trials);

}  // namespace hemiroll::game
