#include "game/research/session/SessionResume.h"

#include <algorithm>
#include <set>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/ResultsFile.h"
#include "engine/record/Sidecar.h"
#include "game/research/session/SessionError.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

constexpr const char* kTrialExtensions[] = {".csv", ".json", ".replay"};

[[noreturn]] void fail(const std::string& message) { throw SessionError(SessionError::Kind::Environment, message); }

// The trial ids results.csv has a row for.
std::set<std::string> finishedIds(const fs::path& folder) {
  record::ResultsTable table;
  try {
    table = record::ResultsFile(folder / "results.csv").read();
  } catch (const record::RecordError& e) {
    fail(e.what());
  }
  std::set<std::string> ids;
  if (table.columns.empty()) return ids;
  const auto column = std::find(table.columns.begin(), table.columns.end(), "trial");
  if (column == table.columns.end()) fail((folder / "results.csv").string() + ": line 1: no 'trial' column");
  const auto at = static_cast<std::size_t>(column - table.columns.begin());
  for (const auto& row : table.rows)
    if (!ids.insert(row[at]).second)
      fail((folder / "results.csv").string() + " lists trial '" + row[at] +
           "' twice (two sessions ran in the folder at once?); move the later row away by hand");
  return ids;
}

bool sidecarComplete(const fs::path& sidecar) {
  std::error_code ec;
  if (!fs::exists(sidecar, ec)) return false;
  try {
    record::TrialMeta meta;
    record::SidecarStatus status;
    record::Sidecar::fromJson(record::readWholeFile(sidecar, files::kSidecar), sidecar.string(), meta, status);
    return status.complete;
  } catch (const record::RecordError&) {
    return false;  // unreadable: treated as interrupted, and moved aside
  }
}

}  // namespace

ManifestAborted moveTrialAside(const fs::path& folder, const std::string& trialId, const std::string& reason) {
  std::error_code ec;
  int n = 1;
  auto taken = [&](int k) {
    return std::any_of(std::begin(kTrialExtensions), std::end(kTrialExtensions), [&](const char* ext) {
      return fs::exists(folder / (trialId + ext + ".aborted-" + std::to_string(k)), ec);
    });
  };
  while (taken(n)) ++n;
  ManifestAborted entry{trialId, record::utcTimestamp(), reason, {}};
  for (const char* ext : kTrialExtensions) {
    const fs::path from = folder / (trialId + ext);
    if (!fs::exists(from, ec)) continue;
    const std::string to = from.filename().string() + ".aborted-" + std::to_string(n);
    fs::rename(from, folder / to, ec);
    if (ec) fail("cannot move " + from.string() + " aside to " + to + ": " + ec.message());
    entry.moved.emplace_back(from.filename().string(), to);
  }
  return entry;
}

ResumePoint findResumePoint(const fs::path& folder, const std::vector<ManifestTrial>& plan) {
  const std::set<std::string> rows = finishedIds(folder);
  for (const std::string& id : rows)
    if (std::none_of(plan.begin(), plan.end(), [&](const ManifestTrial& t) { return t.trialId == id; }))
      fail((folder / "results.csv").string() + " lists trial '" + id + "', which is not in the session's plan");
  ResumePoint point;
  std::vector<bool> complete(plan.size());
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const ManifestTrial& t = plan[i];
    complete[i] = sidecarComplete(folder / (t.trialId + ".json"));
    if (rows.count(t.trialId) == 0) continue;
    if (!complete[i])
      fail((folder / "results.csv").string() + " lists " + t.trialId + " but " + t.trialId +
           ".json is missing or not complete: the folder was changed by hand");
    if (point.done != static_cast<int>(i))
      fail(t.trialId + " is finished but " + plan[static_cast<std::size_t>(point.done)].trialId +
           " is not: the folder was changed by hand");
    point.done = static_cast<int>(i) + 1;
  }
  std::error_code ec;
  for (std::size_t i = static_cast<std::size_t>(point.done); i < plan.size(); ++i) {
    const std::string& id = plan[i].trialId;
    const bool anyFile = std::any_of(std::begin(kTrialExtensions), std::end(kTrialExtensions),
                                     [&](const char* ext) { return fs::exists(folder / (id + ext), ec); });
    if (anyFile)
      point.interrupted.emplace_back(id, complete[i] ? "finished, but its results row was never written"
                                                     : "interrupted before it finished");
  }
  return point;
}

}  // namespace hemiroll::game
