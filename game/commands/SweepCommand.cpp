#include "game/commands/SweepCommand.h"

#include <unistd.h>

#include <iostream>

#include "engine/physics/BatchedRk4.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/script/ScriptError.h"
#include "engine/script/SweepLoader.h"
#include "game/research/analysis/AnalysisOutput.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/commands/SweepOptions.h"
#include "game/trial/JsonLine.h"
#include "game/research/report/Heatmap.h"
#include "game/research/sweep/OrderedPool.h"
#include "game/research/sweep/PhysicsFingerprint.h"
#include "game/research/sweep/SlurmJob.h"
#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepMaps.h"
#include "game/research/sweep/SweepMerge.h"
#include "game/research/sweep/SweepPartRun.h"

#ifndef HEMIROLL_VERSION
#error "HEMIROLL_VERSION must be defined by the build (game/CMakeLists.txt)"
#endif

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

constexpr const char* kProgram = "hemiroll " HEMIROLL_VERSION;

// The maps of a finished sweep in `dir`; returns how many files.
std::size_t writeMaps(const fs::path& dir) {
  const auto sheets = sweepMapSheets(loadSweep(dir));
  try {
    writeOutputFiles(dir.string(), sheets);
  } catch (const record::RecordError& e) {
    throw SweepError(SweepError::Kind::Environment, e.what());
  }
  return sheets.size();
}

// The job files for a cluster; the spec was loaded, so a broken one is
// refused here, not by N tasks on the cluster.
int writeSlurm(const SweepOptions& o) {
  SlurmJobDef def;
  std::error_code ec;
  def.program = fs::canonical("/proc/self/exe", ec);
  if (ec) throw SweepError(SweepError::Kind::Environment, "this program's own path cannot be read: " + ec.message());
  def.spec = fs::absolute(o.inputs.front());
  def.out = fs::absolute(*o.out);
  def.tasks = o.slurmTasks;
  def.threadsPerTask = o.threads > 0 ? o.threads : 1;
  def.maps = o.maps;
  def.resources = o.slurm;
  const SlurmJobWritten written = writeSlurmJob(def);
  const std::vector<fs::path>& files = written.files;
  for (const std::string& note : written.notes) std::cerr << "hemiroll sweep: " << note << "\n";
  if (o.slurm.time.empty())
    std::cerr << "hemiroll sweep: no --slurm-time: the tasks ask for no time limit, which many sites refuse\n";
  std::cerr << "hemiroll sweep: a Slurm job of " << def.tasks << " tasks in " << files.front().parent_path().string()
            << "; submit it with " << files.back().string() << "\n";
  JsonLine line;
  line.add("submit", files.back().string()).add("array", files[0].string()).add("merge", files[1].string());
  line.add("tasks", static_cast<long long>(def.tasks)).add("parts", (def.out / "parts").string());
  std::cout << line.str() << "\n";
  return kExitOk;
}

int runSweep(const SweepOptions& o) {
  SweepPartRequest request;
  try {
    request.def = script::SweepLoader().loadFile(o.inputs.front());
  } catch (const script::ScriptError& e) {
    std::cerr << "hemiroll sweep: " << e.what() << "\n";
    return kExitUsage;
  }
  if (o.slurmTasks > 0) return writeSlurm(o);
  request.specFile = o.inputs.front();
  request.shard = o.shard;
  request.outDir = *o.out;
  request.threads = o.threads > 0 ? o.threads : OrderedPool::defaultThreads();
  request.laneWidth = o.lanes > 0 ? o.lanes : physics::bestLaneWidth();
  if (!physics::laneWidthSupported(request.laneWidth)) {
    std::cerr << "hemiroll sweep: --lanes " << request.laneWidth << " needs "
              << (request.laneWidth == 8 ? "AVX-512" : "AVX2") << ", which this CPU lacks; widths it runs: 1, 2"
              << (physics::laneWidthSupported(4) ? ", 4" : "") << "\n";
    return kExitUsage;
  }
  request.terminal = isatty(STDERR_FILENO) == 1;
  // The version and the physics fingerprint: parts merge and resume only
  // where both agree (PhysicsFingerprint.h).
  request.program = std::string(kProgram) + " (physics " + physicsFingerprint() + ")";
  const SweepPartReport r = runSweepPart(request);
  const std::size_t maps = o.maps && o.shard.whole() ? writeMaps(request.outDir) : 0;
  const double rate = r.wallSeconds > 0.0 ? static_cast<double>(r.computed) / r.wallSeconds : 0.0;
  std::cerr << "hemiroll sweep: " << (r.alreadyComplete ? "already complete: " : "") << r.points << " points (shard "
            << o.shard.label() << ", " << r.resumed << " kept from an earlier run, " << r.computed << " computed on "
            << request.threads << " threads (" << request.laneWidth << " lanes) in " << r.wallSeconds << " s, " << rate << " points/s), " << r.stopped
            << " stopped by a domain event; " << r.csv.string() << (maps > 0 ? " and " + std::to_string(maps) + " maps" : "")
            << "\n";
  std::cout << JsonLine()
                   .add("csv", r.csv.string())
                   .add("manifest", r.manifest.string())
                   .add("points", static_cast<long long>(r.points))
                   .add("computed", static_cast<long long>(r.computed))
                   .add("resumed", static_cast<long long>(r.resumed))
                   .add("stopped", static_cast<long long>(r.stopped))
                   .add("threads", static_cast<long long>(request.threads))
                   .add("lanes", static_cast<long long>(request.laneWidth))
                   .add("wall_s", r.wallSeconds)
                   .add("points_per_s", rate)
                   .add("maps", static_cast<long long>(maps))
                   .str()
            << "\n";
  return kExitOk;
}

int runMerge(const SweepOptions& o) {
  std::vector<fs::path> dirs(o.inputs.begin(), o.inputs.end());
  const MergedSweep merged = mergeSweepParts(dirs);
  writeMergedSweep(merged, *o.out);
  const std::size_t maps = o.maps ? writeMaps(*o.out) : 0;
  std::cerr << "hemiroll sweep merge: " << merged.parts << " parts, " << merged.manifest.pointsTotal << " points -> "
            << (fs::path(*o.out) / "sweep.csv").string() << (maps > 0 ? " and " + std::to_string(maps) + " maps" : "")
            << "\n";
  std::cout << JsonLine()
                   .add("csv", (fs::path(*o.out) / "sweep.csv").string())
                   .add("parts", static_cast<long long>(merged.parts))
                   .add("points", merged.manifest.pointsTotal)
                   .add("spec_hash", merged.manifest.specHash)
                   .add("maps", static_cast<long long>(maps))
                   .str()
            << "\n";
  return kExitOk;
}

int runMap(const SweepOptions& o) {
  const fs::path dir = o.inputs.front();
  const SweepData data = loadSweep(dir);
  MapRequest request;
  for (auto [name, param] : {std::pair{&o.x, &request.x}, std::pair{&o.y, &request.y}}) {
    const auto found = task::findSweepParam(**name);
    if (!found)
      throw SweepError(SweepError::Kind::BadInput,
                       "unknown parameter '" + **name + "' (expected R, m_s, m_p, g, r1, r2, k or Omega)");
    *param = *found;
  }
  request.metric = findSweepMetric(*o.metric);
  request.aggregate = o.aggregate;
  const fs::path out = o.out ? fs::path(*o.out) : dir / ("map-" + *o.x + "-" + *o.y + "-" + *o.metric + ".svg");
  try {
    record::writeFileAtomically(out, report::renderHeatmap(sweepHeatmap(data, request), 720.0, 540.0));
  } catch (const record::RecordError& e) {
    throw SweepError(SweepError::Kind::Environment, e.what());
  }
  std::cerr << "hemiroll sweep map: " << out.string() << "\n";
  std::cout << JsonLine().add("svg", out.string()).str() << "\n";
  return kExitOk;
}

}  // namespace

int runSweepCommand(const std::vector<std::string>& args) {
  const SweepOptionsResult parsed = parseSweepOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning("hemiroll sweep: ", parsed, sweepUsage())) return *exit;
  const SweepOptions& o = parsed.options;
  try {
    switch (o.action) {
      case SweepAction::Run: return runSweep(o);
      case SweepAction::Merge: return runMerge(o);
      case SweepAction::Map: return runMap(o);
    }
  } catch (const SweepError& e) {
    std::cerr << "hemiroll sweep: " << e.what() << "\n";
    return e.kind() == SweepError::Kind::BadInput ? kExitUsage : kExitFailure;
  }
  return kExitOk;
}

}  // namespace hemiroll::game
