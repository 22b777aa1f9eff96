#pragma once
// The table over all trials of one `hemiroll analyze`: a CSV (SI columns
// with unit suffixes, empty where a feature was not found) and a markdown
// table for people (cm, the features found, "-" otherwise).

#include <string>
#include <vector>

#include "engine/analysis/TrialAnalyzer.h"
#include "game/research/analysis/TrialData.h"

namespace hemiroll::game {

struct AnalysedTrial {
  TrialData data;
  analysis::TrialFeatures features;
  analysis::GuidanceWork guidance;
};

std::string featureTableCsv(const std::vector<AnalysedTrial>& trials);
// The CSV's columns after `trial` and `source`, and one trial's cells for them.
std::vector<std::string> featureColumns();
std::vector<std::string> featureCells(const AnalysedTrial& trial);
std::string featureTableMarkdown(const std::vector<AnalysedTrial>& trials);

}  // namespace hemiroll::game
