#pragma once
// The inputs of `hemiroll analyze`, as trials: a trial CSV with its JSON
// sidecar (engine/record's RecordingReader; an interrupted recording's cut
// last line is dropped with a note), a session folder (every trial CSV in
// it, in name order; results.csv, the session's summary, and analysis.csv,
// an earlier analysis written there, are not trials), or
// a `hemiroll sim` CSV. Trial ids come from the file names and are made
// unique ("-2", "-3", ...) when two inputs share one.

#include <string>
#include <vector>

#include "game/research/analysis/TrialData.h"

namespace hemiroll::game {

// Throws AnalysisInputError (one sentence naming the file and line) for a
// missing file, an unknown or broken CSV, a missing or broken sidecar, or a
// folder without trials.
std::vector<TrialData> loadTrials(const std::vector<std::string>& paths);

}  // namespace hemiroll::game
