#include "game/research/sweep/SweepPartRun.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <system_error>
#include <vector>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/files/LineReader.h"
#include "engine/files/PrintableName.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/ResultsFile.h"
#include "game/research/sweep/OrderedPool.h"
#include "game/research/sweep/PointMeasurement.h"
#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepGrid.h"
#include "game/research/sweep/SweepManifest.h"
#include "game/research/sweep/SweepProgress.h"
#include "game/research/sweep/SweepSpecJson.h"
#include "game/research/sweep/SweepTable.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void environment(const std::string& message) { throw SweepError(SweepError::Kind::Environment, message); }

// A row as this program writes it for `point` (sweepRowProblem).
bool isSweepRowFor(std::string_view line, long long point) {
  const std::optional<std::vector<std::string>> fields = record::parseCsvLine(std::string(line) + "\n");
  return fields && !fields->empty() && (*fields)[0] == std::to_string(point) && sweepRowProblem(*fields).empty();
}

// The rows of an interrupted run that can be kept: whole lines after the
// header, the shard's first points in order, read as a stream through the
// checked reader. Rows never hold a line break (PointMeasurement::notes),
// so a cut line is one without its '\n'.
std::vector<std::string> keptRows(const fs::path& partial, const std::vector<long long>& points) {
  std::error_code ec;
  if (!fs::exists(partial, ec) && !fs::is_symlink(partial, ec)) return {};
  std::vector<std::string> rows;
  try {
    files::CheckedFile file(partial, files::kSweepTable);
    files::LineReader lines(file, kMaxSweepLineBytes);
    std::string_view line;
    bool complete = false;
    const std::string header = sweepHeader();
    if (!lines.next(line, complete) || !complete || std::string(line) + "\n" != header)
      return {};  // another program's columns: start clean
    while (rows.size() < points.size() && lines.next(line, complete) && complete) {
      // Kept only as this program writes it: a tampered or damaged row would
      // be copied into a part marked complete and break every later read.
      if (!isSweepRowFor(line, points[rows.size()])) break;
      rows.push_back(std::string(line) + "\n");
    }
  } catch (const files::FileReadError& e) {
    environment(e.what());
  }
  return rows;
}

void writeManifest(const fs::path& path, const SweepManifest& m,
                   record::DirectorySync sync = record::DirectorySync::Now) {
  try {
    record::writeFileAtomically(path, manifestJson(m), sync);
  } catch (const record::RecordError& e) {
    environment(e.what());
  }
}

long long stoppedRows(const fs::path& csv) {
  const std::size_t event = sweepColumn("event");
  const auto rows = readSweepRows(csv);
  return std::count_if(rows.begin(), rows.end(), [&](const std::vector<std::string>& row) { return row[event] != "none"; });
}

// The part's manifest before its first row: which spec, shard and program.
SweepManifest manifestOf(const SweepPartRequest& r, const SweepGrid& grid, const SweepPartReport& report) {
  SweepManifest m;
  m.program = r.program;
  m.specFile = files::printable(r.specFile);  // text in JSON: \xNN for bytes that are not UTF-8
  m.description = r.def.description;
  m.specHash = specHash(r.def);
  m.specJson = specJson(r.def);
  m.pointsTotal = grid.size();
  m.shard = r.shard;
  m.pointCount = report.points;
  m.csv = report.csv.filename().string();
  m.threads = r.threads;
  return m;
}

// What an earlier run left in the folder: nothing, an interrupted part (its
// rows may be kept) or a complete one. Another sweep's part is refused.
enum class EarlierRun { None, Interrupted, Complete };

EarlierRun earlierRun(const SweepPartRequest& r, const SweepManifest& m, const SweepPartReport& report) {
  std::error_code ec;
  if (!fs::exists(report.manifest, ec)) return EarlierRun::None;
  const SweepManifest old = readManifest(report.manifest);
  if (old.specHash != m.specHash || old.program != m.program)
    throw SweepError(SweepError::Kind::BadInput,
                     r.outDir.string() + " already holds shard " + r.shard.label() + " of another sweep (" +
                         old.specHash + " by " + old.program + "; this is " + m.specHash + " by " + m.program +
                         "): give another --out or remove " + report.manifest.filename().string());
  if (old.complete && fs::exists(report.csv, ec)) return EarlierRun::Complete;
  return old.complete ? EarlierRun::None : EarlierRun::Interrupted;
}

// The shard's points after the kept ones, in jobs of up to laneWidth points
// integrated together, on the ordered pool; rows appended to `out` in point
// order as jobs finish.
void computeRows(const SweepPartRequest& r, const SweepGrid& grid, const std::vector<long long>& points,
                 std::size_t first, record::DurableFile& out, SweepProgress& progress) {
  const std::size_t batch = static_cast<std::size_t>(std::max(1, r.laneWidth));
  const std::size_t remaining = points.size() - first;
  std::size_t delivered = 0;  // points, on the delivering thread
  OrderedPool(r.threads).run(
      (remaining + batch - 1) / batch,
      [&](std::size_t job) {
        std::vector<SweepPoint> jobPoints;
        for (std::size_t i = first + job * batch; i < std::min(points.size(), first + (job + 1) * batch); ++i)
          jobPoints.push_back(grid.point(points[i]));
        const std::vector<PointMeasurement> measured = measurePoints(grid, jobPoints, r.laneWidth);
        std::string rows;
        for (std::size_t i = 0; i < jobPoints.size(); ++i) rows += sweepRow(jobPoints[i], measured[i]);
        return rows;
      },
      [&](std::size_t job, std::string&& rows) {
        if (!out.write(rows) || !out.flush()) environment(out.path().string() + ": " + out.error());
        delivered = std::min(remaining, (job + 1) * batch);
      },
      // Off a terminal the bar draws nothing: no tick, and one thread then
      // needs no pool (OrderedPool::run).
      r.terminal ? OrderedPool::Tick([&](std::size_t) { progress.update(static_cast<long long>(first + delivered)); })
                 : OrderedPool::Tick());
}

}  // namespace

// Manifest, what an earlier run left, the rows (kept, then computed into
// CSV.partial, moved into place when whole), the manifest complete.
SweepPartReport runSweepPart(const SweepPartRequest& r) {
  const SweepGrid grid(r.def);
  const std::vector<long long> points = r.shard.points(grid.size());
  SweepPartReport report;
  report.points = static_cast<long long>(points.size());
  report.manifest = r.outDir / (r.shard.stem() + ".json");
  report.csv = r.outDir / (r.shard.stem() + ".csv");
  const fs::path partial = r.outDir / (r.shard.stem() + ".csv.partial");
  SweepManifest m = manifestOf(r, grid, report);

  std::error_code ec;
  fs::create_directories(r.outDir, ec);
  if (!fs::is_directory(r.outDir, ec)) environment("cannot create the output folder " + r.outDir.string());
  const EarlierRun earlier = earlierRun(r, m, report);
  if (earlier == EarlierRun::Complete) {
    report.alreadyComplete = true;
    report.resumed = report.points;
    report.stopped = stoppedRows(report.csv);
    return report;
  }

  const std::vector<std::string> kept =
      earlier == EarlierRun::Interrupted ? keptRows(partial, points) : std::vector<std::string>{};
  report.resumed = static_cast<long long>(kept.size());
  m.resumedPoints = report.resumed;
  // Durable with the partial table's rename below, by the one sync of the
  // folder that follows it. A crash before that sync leaves either manifest
  // (the new one, or the earlier run's: the same sweep's, else the folder was
  // refused above, or none) beside either partial table (the new one, holding
  // only rows kept, or the earlier one): a rerun keeps what the manifest
  // allows and computes the rest, the same bytes. Rows are computed only
  // after the sync, so none is ever durable before the manifest naming its
  // sweep.
  writeManifest(report.manifest, m, record::DirectorySync::Deferred);
  std::string start = sweepHeader();
  for (const std::string& row : kept) start += row;
  SweepProgress progress(stderr, report.points, report.resumed, r.terminal);
  try {
    record::writeFileAtomically(partial, start);
    // The rename that just put `partial` in place was synced with its
    // directory: the entry is durable, and opening it again adds no entry.
    record::DurableFile out(partial, "ab", record::DurableFile::Entry::AlreadyCovered);
    computeRows(r, grid, points, kept.size(), out, progress);
    if (!out.close()) environment(out.path().string() + ": " + out.error());
    report.computed = report.points - report.resumed;
    progress.finish(report.points);
    record::moveFileDurably(partial, report.csv);
  } catch (const record::RecordError& e) {
    environment(e.what());
  }
  report.wallSeconds = progress.elapsedSeconds();
  m.complete = true;
  m.wallSeconds = report.wallSeconds;
  writeManifest(report.manifest, m);
  report.stopped = stoppedRows(report.csv);
  return report;
}

}  // namespace hemiroll::game
