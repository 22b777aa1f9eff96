#include "game/research/sweep/SweepMerge.h"

#include <algorithm>
#include <regex>
#include <system_error>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/task/SweepDef.h"
#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepTable.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void badInput(const std::string& message) { throw SweepError(SweepError::Kind::BadInput, message); }

struct Part {
  fs::path manifestPath;
  SweepManifest manifest;
  std::vector<std::vector<std::string>> rows;
};

Part readPart(const fs::path& manifestPath) {
  Part p{manifestPath, readManifest(manifestPath), {}};
  const SweepManifest& m = p.manifest;
  if (!m.complete)
    badInput(manifestPath.string() + ": shard " + m.shard.label() +
             " is incomplete (its run was interrupted or is still going; run it again to finish it)");
  const fs::path csv = manifestPath.parent_path() / m.csv;
  p.rows = readSweepRows(csv);
  if (static_cast<long long>(p.rows.size()) != m.pointCount)
    badInput(csv.string() + " holds " + std::to_string(p.rows.size()) + " rows; its manifest says " +
             std::to_string(m.pointCount));
  const std::size_t point = sweepColumn("point");
  for (std::size_t j = 0; j < p.rows.size(); ++j) {
    const long long expected = m.shard.index + static_cast<long long>(j) * m.shard.count;
    if (p.rows[j][point] != std::to_string(expected))
      badInput(csv.string() + ": row " + std::to_string(j + 2) + " is point " + p.rows[j][point] + ", expected " +
               std::to_string(expected) + " (shard " + m.shard.label() + ")");
  }
  return p;
}

// "; shards 1/4, 3/4 were not given" when every part has the same N.
std::string missingShards(const std::vector<Part>& parts) {
  const long long n = parts.front().manifest.shard.count;
  std::vector<bool> given(static_cast<std::size_t>(n), false);
  for (const Part& p : parts) {
    if (p.manifest.shard.count != n) return "";
    given[static_cast<std::size_t>(p.manifest.shard.index)] = true;
  }
  std::string list;
  int count = 0;
  for (long long i = 0; i < n; ++i)
    if (!given[static_cast<std::size_t>(i)]) {
      list += (list.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(n);
      ++count;
    }
  return list.empty() ? "" : (count == 1 ? " (shard " : " (shards ") + list + " not given?)";
}

}  // namespace

std::vector<fs::path> sweepPartsIn(const fs::path& dir) {
  static const std::regex kPart(R"(sweep\.json|part-[0-9]+-of-[0-9]+\.json)");
  std::vector<fs::path> found;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file(ec) && std::regex_match(e.path().filename().string(), kPart)) found.push_back(e.path());
  std::sort(found.begin(), found.end());
  return found;
}

MergedSweep mergeSweepParts(const std::vector<fs::path>& dirs) {
  std::vector<Part> parts;
  for (const fs::path& dir : dirs) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) badInput(dir.string() + " is not a folder");
    const std::vector<fs::path> manifests = sweepPartsIn(dir);
    if (manifests.empty()) badInput(dir.string() + " holds no sweep parts (sweep.json or part-<i>-of-<N>.json)");
    for (const fs::path& m : manifests) parts.push_back(readPart(m));
  }
  if (parts.empty()) badInput("no folders to merge");
  const SweepManifest& first = parts.front().manifest;
  for (const Part& p : parts) {
    if (p.manifest.specHash != first.specHash)
      badInput(p.manifestPath.string() + " comes from another sweep spec (" + p.manifest.specHash + ", not " +
               first.specHash + " as " + parts.front().manifestPath.string() + ")");
    if (p.manifest.program != first.program)
      badInput(p.manifestPath.string() + " was written by " + p.manifest.program + ", " +
               parts.front().manifestPath.string() + " by " + first.program + "; merge parts of one build only");
  }

  // points_total is not covered by the spec hash: a forged or damaged one
  // must be refused before it sizes anything, and every part must agree.
  if (first.pointsTotal < 1 || first.pointsTotal > task::kMaxSweepPoints)
    badInput(parts.front().manifestPath.string() + " says points_total = " + std::to_string(first.pointsTotal) +
             "; a sweep has 1 to " + std::to_string(task::kMaxSweepPoints) + " points");
  for (const Part& p : parts)
    if (p.manifest.pointsTotal != first.pointsTotal)
      badInput(p.manifestPath.string() + " says points_total = " + std::to_string(p.manifest.pointsTotal) + ", " +
               parts.front().manifestPath.string() + " " + std::to_string(first.pointsTotal));
  std::vector<int> owner(static_cast<std::size_t>(first.pointsTotal), -1);
  std::vector<const std::vector<std::string>*> rows(owner.size(), nullptr);
  const std::size_t point = sweepColumn("point");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    for (const auto& row : parts[i].rows) {
      const auto at = static_cast<std::size_t>(std::stoll(row[point]));  // checked against the manifest
      if (owner[at] >= 0)
        badInput("point " + row[point] + " is in both " + parts[static_cast<std::size_t>(owner[at])].manifestPath.string() +
                 " and " + parts[i].manifestPath.string() + " (a shard given twice?)");
      owner[at] = static_cast<int>(i);
      rows[at] = &row;
    }
  }
  const auto missing = std::count(owner.begin(), owner.end(), -1);
  if (missing > 0)
    badInput(std::to_string(missing) + " of " + std::to_string(owner.size()) + " points are missing, the first is point " +
             std::to_string(std::find(owner.begin(), owner.end(), -1) - owner.begin()) + missingShards(parts));

  MergedSweep out;
  out.parts = static_cast<int>(parts.size());
  out.manifest = first;
  out.manifest.shard = SweepShard{};
  out.manifest.pointCount = first.pointsTotal;
  out.manifest.csv = "sweep.csv";
  out.manifest.complete = true;
  out.manifest.threads = 0;
  out.manifest.wallSeconds = 0.0;
  out.manifest.resumedPoints = 0;
  out.csv = sweepHeader();
  for (const auto* row : rows) out.csv += record::csvLine(*row);
  return out;
}

void writeMergedSweep(const MergedSweep& merged, const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  try {
    record::writeFileAtomically(dir / "sweep.csv", merged.csv);
    record::writeFileAtomically(dir / "sweep.json", manifestJson(merged.manifest));
  } catch (const record::RecordError& e) {
    throw SweepError(SweepError::Kind::Environment, e.what());
  }
}

}  // namespace hemiroll::game
