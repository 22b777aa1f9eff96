#pragma once
// Learning curves of an experiment (docs/ANALYSIS.md "An experiment"): per
// participant and per group, the mean and spread of a trial measure by
// trial (the trial's place in its session: practice) and by block.
//
//   participant, by trial: the participant's value at each trial index (n 1;
//     sessions of one participant at the same index are pooled)
//   participant, by block: the mean (sd) over the participant's trials of
//     each block
//   group, by trial: the mean (sd) over the group's participants of their
//     values at each trial index; n participants
//   group, by block: the mean (sd) over the group's participants of their
//     block means
// sd is the sample standard deviation (n - 1), empty for n < 2. A block's x
// is its rank in the file's order (the order of participants with block
// order 1, or else of the lowest order present), so a counterbalanced
// block has one place on every curve.

#include <string>
#include <vector>

#include "game/research/analysis/AnalysisOutput.h"
#include "game/research/analysis/ExperimentTable.h"

namespace hemiroll::game {

struct CurvePoint {
  std::string scope;        // "participant" or "group"
  std::string participant;  // "" for a group's point
  std::string group;
  std::string by;           // "trial" or "block"
  double x = 0.0;           // trial index, or block rank (1-based)
  std::string blockName;    // "" by trial
  std::string measure;      // a column of the long table
  int n = 0;
  double mean = 0.0;
  double sd = 0.0;          // NaN for n < 2
};

// The measures curves are drawn for by default: trial success (0/1, so its
// mean is the success rate), time [s], the end's margin and the contact
// point's path [m].
const std::vector<std::string>& defaultCurveMeasures();

std::vector<CurvePoint> learningCurves(const std::vector<ExperimentTrial>& trials,
                                       const std::vector<std::string>& measures);
// Long format: scope, participant, group, by, x, block_name, measure, n, mean, sd.
std::string learningCurvesCsv(const std::vector<CurvePoint>& points);
// SVG plots (game/research/report's LinePlot), per measure: the groups' mean and
// mean +- sd by trial and by block, and every participant by trial.
OutputFiles learningCurvePlots(const std::vector<CurvePoint>& points, const std::vector<std::string>& measures);

}  // namespace hemiroll::game
