#include "game/commands/SimCommand.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

#include "engine/physics/IntegratorRegistry.h"
#include "engine/physics/RotationDrivenSystem.h"
#include "engine/script/ScenarioLoader.h"
#include "engine/script/ScriptError.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/commands/SimOptions.h"
#include "game/research/sim/CsvTrajectoryWriter.h"
#include "game/research/sim/ScenarioRun.h"

namespace hemiroll::game {

namespace {

// More steps than this is a typo in --dt, not a simulation.
constexpr double kMaxSteps = 1e10;

void listIntegrators() {
  for (const auto& info : physics::IntegratorRegistry::builtin().list())
    std::printf("%-8s order %d  %s\n", info.name.c_str(), info.order, info.description.c_str());
}

RunSettings resolveSettings(const SimOptions& o, const task::ScenarioDef& scenario) {
  RunSettings s;
  s.duration = o.duration.value_or(scenario.duration.value_or(SimOptions::kDefaultDuration));
  s.timeStep = o.timeStep.value_or(scenario.timeStep.value_or(SimOptions::kDefaultTimeStep));
  s.integrator = o.integrator.value_or(scenario.integrator.value_or(SimOptions::kDefaultIntegrator));
  s.every = o.every;
  s.tolerance = o.tolerance.value_or(scenario.tolerance.value_or(SimOptions::kDefaultTolerance));
  // Both names were checked when they were read (flags and scenario alike).
  if (const auto form = o.orientation ? o.orientation : scenario.orientation)
    physics::parseOrientationForm(*form, s.orientation);
  return s;
}

// Closes a file opened for --out on every path out of the command.
class OutputFile {
 public:
  ~OutputFile() {
    if (file_ != nullptr && file_ != stdout) std::fclose(file_);
  }
  bool open(const std::optional<std::string>& path) {
    file_ = path ? std::fopen(path->c_str(), "wb") : stdout;
    return file_ != nullptr;
  }
  // Flushes and, for a file, closes; false if anything failed on the way.
  bool finish() {
    bool ok = std::fflush(file_) == 0 && std::ferror(file_) == 0;
    if (file_ != stdout) {
      ok = std::fclose(file_) == 0 && ok;
      file_ = nullptr;
    }
    return ok;
  }
  std::FILE* get() const { return file_; }

 private:
  std::FILE* file_ = nullptr;
};

}  // namespace

int runSimCommand(const std::vector<std::string>& args) {
  const SimOptionsResult parsed = parseSimOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning("hemiroll sim: ", parsed, simUsage())) return *exit;
  const SimOptions& options = parsed.options;
  if (options.listIntegrators) {
    listIntegrators();
    return kExitOk;
  }

  task::ScenarioDef scenario;
  try {
    scenario = script::ScenarioLoader().loadFile(options.scenarioPath);
  } catch (const script::ScriptError& e) {
    std::cerr << "hemiroll sim: " << e.what() << "\n";
    return kExitUsage;
  }
  const RunSettings settings = resolveSettings(options, scenario);
  if (settings.duration / settings.timeStep > kMaxSteps) {
    std::cerr << "hemiroll sim: duration / dt asks for more than 1e10 steps; check --dt\n";
    return kExitUsage;
  }
  // Measured on the shipped scenarios: 220 (tether) to 330 (rose) bytes a row.
  constexpr double kCsvBytesPerRow = 300.0;
  // Rows the run would write (a grid point every `every` steps, the first
  // and the last): told before a byte is written, not found on a full disk.
  const double rows = std::floor(settings.duration / settings.timeStep / static_cast<double>(settings.every)) + 2.0;
  if (rows > static_cast<double>(options.maxRows)) {
    std::cerr << "hemiroll sim: the run would write about " << static_cast<long long>(rows) << " rows (about "
              << std::lround(rows * kCsvBytesPerRow / 1e9) << " GB of CSV), more than --max-rows " << options.maxRows
              << "; thin it with --every or raise --max-rows\n";
    return kExitUsage;
  }
  if (settings.orientation == physics::OrientationForm::Quaternion && scenario.drive.kind == task::DriveKind::Rose) {
    std::cerr << "hemiroll sim: --orientation quaternion applies to free and proxy drives; " << options.scenarioPath
              << " uses the rose drive (the 8-state prescribed model)\n";
    return kExitUsage;
  }

  OutputFile out;
  if (!out.open(options.outPath)) {
    std::cerr << "hemiroll sim: cannot open '" << *options.outPath << "' for writing: " << std::strerror(errno) << "\n";
    return kExitFailure;
  }
  // A large buffer: a 35 s run at 1 ms is 35001 rows of ~19 numbers.
  std::setvbuf(out.get(), nullptr, _IOFBF, 1 << 16);

  const ScenarioRun run(scenario, settings);
  CsvTrajectoryWriter writer(out.get(), run.hasHandForce());
  writer.writeHeader();
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  try {
    summary = run.run([&](const TrajectoryRow& row) { writer.writeRow(row); });
  } catch (const script::ScriptError& e) {
    // A proxy function failed part-way: the CSV written so far is incomplete.
    out.finish();
    std::cerr << "hemiroll sim: " << e.what() << "\n";
    return kExitUsage;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const bool written = writer.good();  // ask before finish() closes the file
  if (!out.finish() || !written) {
    std::cerr << "hemiroll sim: writing the CSV failed" << (options.outPath ? " ('" + *options.outPath + "')" : "")
              << "\n";
    return kExitFailure;
  }
  if (summary.event != physics::DomainEvent::None) {
    std::fprintf(stderr, "hemiroll sim: event %s at t = %.9g s; the run stopped there (last row)\n",
                 physics::domainEventName(summary.event), summary.endTime);
  }
  std::fprintf(stderr,
               "hemiroll sim: %s drive, %lld steps of %.9g s (%s), simulated %.9g s, %lld rows, "
               "final energy %.9g J, wall %.3f s\n",
               task::driveKindName(scenario.drive.kind), summary.steps, settings.timeStep,
               settings.integrator.c_str(), summary.endTime, writer.rowsWritten(), summary.finalEnergy, wall);
  return kExitOk;
}

}  // namespace hemiroll::game
