#pragma once
// An experiment folder (<data root>/<experiment>/<participant>/<session>/,
// docs/PROTOCOLS.md) as one long-format table: one row per finished trial
// of every session, its place (participant, group, block order, block,
// condition, trial in block), how it ended, results.csv's per-trial
// measures and the movement features `hemiroll analyze` finds in its
// samples (columns prefixed movement_). What `hemiroll analyze
// EXPERIMENT_FOLDER` writes as trials.csv (docs/ANALYSIS.md "An experiment").

#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace hemiroll::game {

// What the learning curves need of a trial, typed.
struct ExperimentTrial {
  std::string participant, session, group, blockName;
  int blockOrder = 1;    // the participant's block order (1-based)
  int trialIndex = 0;    // 1-based place in its session
  int block = 0;         // 1-based place of its block in the session
  int trialInBlock = 0;
  std::map<std::string, double> measures;  // numeric cells by column (success is 1 or 0); NaN: empty
};

struct ExperimentTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<ExperimentTrial> trials;  // one per row, in the same order
  std::vector<std::string> notes;       // what could not be read, one sentence each
  int sessions = 0;

  std::string csv() const;
};

// Whether `folder` is an experiment's (or a data root's): no session.json
// of its own, and session folders one or two levels down.
bool isExperimentFolder(const std::filesystem::path& folder);

// Reads every session under `folder` (BidsDataset's sessionFolders) in
// order: participant, then session. A trial whose samples cannot be
// analysed keeps its row with empty movement columns and a note. Throws
// AnalysisInputError for a folder without sessions, or a session whose
// manifest or results.csv cannot be read.
ExperimentTable readExperiment(const std::filesystem::path& folder);

}  // namespace hemiroll::game
