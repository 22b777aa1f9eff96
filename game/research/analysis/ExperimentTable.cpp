#include "game/research/analysis/ExperimentTable.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <system_error>
#include <tuple>

#include "engine/files/FileKinds.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/ResultsFile.h"
#include "game/research/analysis/AnalysisInputError.h"
#include "game/research/analysis/FeatureTable.h"
#include "game/research/analysis/TrialLoader.h"
#include "game/research/session/BidsDataset.h"
#include "game/research/session/SessionFolder.h"
#include "game/research/session/SessionManifest.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

// The trial's place and how it ended, first, in this order (results.csv's
// name where it differs: duration_s -> time_s).
const std::vector<std::string> kLeading = {"participant", "session",        "group",          "block_order",
                                           "trial_index", "trial",          "block",          "block_name",
                                           "trial_in_block", "repetition",  "condition",      "condition_label",
                                           "level",       "outcome",        "success",        "time_s",
                                           "score"};
// results.csv's bookkeeping, not a trial's data.
const std::vector<std::string> kLeftOut = {"level_hash", "rows", "dropped_rows", "start_time", "duration_s"};

bool contains(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

double numberOf(const std::string& cell) {
  if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  return end == cell.c_str() + cell.size() ? v : std::numeric_limits<double>::quiet_NaN();
}

int integerOf(const std::string& cell) {
  const double v = numberOf(cell);
  return std::isfinite(v) ? static_cast<int>(v) : 0;
}

struct SessionRows {
  SessionManifest manifest;
  record::ResultsTable results;
  fs::path folder;
};

}  // namespace

std::string ExperimentTable::csv() const {
  std::string out = record::csvLine(columns);
  for (const auto& row : rows) out += record::csvLine(row);
  return out;
}

bool isExperimentFolder(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec) || fs::exists(folder / kManifestFile, ec)) return false;
  return !sessionFolders(folder).empty();
}

ExperimentTable readExperiment(const fs::path& folder) {
  ExperimentTable table;
  std::vector<SessionRows> sessions;
  for (const fs::path& s : sessionFolders(folder)) {
    SessionRows one;
    one.folder = s;
    const fs::path manifest = s / kManifestFile;
    try {
      one.manifest = SessionManifest::fromJson(record::readWholeFile(manifest, files::kSessionManifest), manifest.string());
      one.results = record::ResultsFile(s / "results.csv").read();
    } catch (const std::exception& e) {
      throw AnalysisInputError(e.what());
    }
    sessions.push_back(std::move(one));
  }
  if (sessions.empty()) throw AnalysisInputError(folder.string() + ": holds no session folders (session.json)");
  std::sort(sessions.begin(), sessions.end(), [](const SessionRows& a, const SessionRows& b) {
    return std::tie(a.manifest.participant, a.manifest.session) < std::tie(b.manifest.participant, b.manifest.session);
  });
  // Columns: the leading ones, then every other results.csv column in the
  // order first met (sessions of one version share them), then movement.
  table.columns = kLeading;
  for (const SessionRows& s : sessions)
    for (const std::string& c : s.results.columns)
      if (!contains(table.columns, c) && !contains(kLeftOut, c)) table.columns.push_back(c);
  const std::size_t movementStart = table.columns.size();
  for (const std::string& c : featureColumns()) table.columns.push_back("movement_" + c);

  for (const SessionRows& s : sessions) {
    ++table.sessions;
    for (const std::vector<std::string>& fields : s.results.rows) {
      std::map<std::string, std::string> cells;
      for (std::size_t c = 0; c < s.results.columns.size() && c < fields.size(); ++c)
        cells[s.results.columns[c]] = fields[c];
      cells["participant"] = s.manifest.participant;
      cells["session"] = s.manifest.session;
      if (cells["group"].empty()) cells["group"] = s.manifest.group;
      if (cells["block_order"].empty()) cells["block_order"] = std::to_string(s.manifest.blockOrder);
      // One character assigned, not a literal: GCC 12 warns on the latter here (-Wrestrict, a false positive).
      cells["success"].assign(1, cells["outcome"] == "success" ? '1' : '0');
      cells["time_s"] = cells["duration_s"];
      std::vector<std::string> row;
      for (std::size_t c = 0; c < movementStart; ++c) row.push_back(cells[table.columns[c]]);
      // The movement features of the trial's samples.
      std::vector<std::string> movement(featureColumns().size());
      try {
        std::vector<TrialData> data = loadTrials({(s.folder / (cells["trial"] + ".csv")).string()});
        AnalysedTrial t{std::move(data.front()), {}, {}};
        t.features = analysis::analyzeTrial(t.data.samples());
        t.guidance = analysis::guidanceWork(t.data.guidanceSamples());
        movement = featureCells(t);
      } catch (const std::exception& e) {
        table.notes.push_back(s.folder.string() + "/" + cells["trial"] + ": no movement features (" + e.what() + ")");
      }
      for (std::string& m : movement) row.push_back(std::move(m));

      ExperimentTrial trial;
      trial.participant = s.manifest.participant;
      trial.session = s.manifest.session;
      trial.group = cells["group"];
      trial.blockName = cells["block_name"];
      trial.blockOrder = std::max(1, integerOf(cells["block_order"]));
      trial.trialIndex = integerOf(cells["trial_index"]);
      trial.block = integerOf(cells["block"]);
      trial.trialInBlock = integerOf(cells["trial_in_block"]);
      for (std::size_t c = 0; c < table.columns.size(); ++c) {
        const double v = numberOf(row[c]);
        if (std::isfinite(v)) trial.measures[table.columns[c]] = v;
      }
      table.rows.push_back(std::move(row));
      table.trials.push_back(std::move(trial));
    }
  }
  return table;
}

}  // namespace hemiroll::game
