#include "game/commands/FiguresCommand.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "engine/physics/DomainEvents.h"
#include "engine/physics/StateLayout.h"
#include "engine/record/RecordError.h"
#include "engine/script/ScenarioLoader.h"
#include "engine/script/ScriptError.h"
#include "game/research/analysis/PaperFigures.h"
#include "game/cli/ArgumentReader.h"
#include "game/commands/ExitCode.h"
#include "game/research/sim/ScenarioRun.h"

namespace hemiroll::game {

namespace {

constexpr const char* kScenario = "levels/scenarios/rose_paper.lua";

const char* figuresUsage() {
  return "usage: hemiroll figures --out DIR [--scenario FILE]\n"
         "\n"
         "Regenerates Figs. 9, 10 and 11 of Svinin et al. (2009), Sec. 5, from the\n"
         "simulator: the prescribed rose drive (eqs. 46-50) with the paper's parameters,\n"
         "35 s, RK4 at h = 1 ms, as the scenario file sets them. Writes\n"
         "fig09_mass_point_rose.svg, fig10_contact_trajectory.svg,\n"
         "fig11_precession_angle.svg and the features measured on the run\n"
         "(figures_features.json, figures_features.md; docs/FIGURES.md).\n"
         "\n"
         "  --out DIR        where to write the files (created if needed)\n"
         "  --scenario FILE  a rose-drive scenario (default: levels/scenarios/rose_paper.lua,\n"
         "                   looked for in the working folder, then beside the program)\n"
         "  --help           print this help\n"
         "\n"
         "Exit codes: 0 done, 1 a file could not be written, 2 bad input.\n";
}

// The default scenario: in the working folder (a checkout), else one or two
// folders above the program (build/hemiroll in a checkout).
std::string defaultScenario() {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_regular_file(kScenario, ec)) return kScenario;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const fs::path& base : {exe.parent_path(), exe.parent_path().parent_path()})
      if (fs::is_regular_file(base / kScenario, ec)) return (base / kScenario).string();
  return kScenario;
}

}  // namespace

int runFiguresCommand(const std::vector<std::string>& args) {
  std::optional<std::string> outDir, scenarioPath;
  bool help = false;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { help = true; })
      .flag("-h", [&] { help = true; })
      .option("--out", cli::text(outDir, "a directory"))
      .option("--scenario", cli::text(scenarioPath, "a scenario file"));
  std::string error = reader.read(args);
  if (error.empty() && !help && !outDir) error = "missing --out DIR";
  if (!error.empty()) {
    std::cerr << "hemiroll figures: " << error << "\n\n" << figuresUsage();
    return kExitUsage;
  }
  if (help) {
    std::cout << figuresUsage();
    return kExitOk;
  }

  task::ScenarioDef scenario;
  const std::string path = scenarioPath.value_or(defaultScenario());
  try {
    scenario = script::ScenarioLoader().loadFile(path);
  } catch (const script::ScriptError& e) {
    std::cerr << "hemiroll figures: " << e.what() << "\n";
    return kExitUsage;
  }
  if (scenario.drive.kind != task::DriveKind::Rose) {
    std::cerr << "hemiroll figures: " << path << ": drive.kind is '" << task::driveKindName(scenario.drive.kind)
              << "'; the paper's figures come from the rose drive\n";
    return kExitUsage;
  }

  FigureRun run;
  run.rose = scenario.drive.rose;
  RunSettings settings;
  settings.duration = scenario.duration.value_or(35.0);
  settings.timeStep = run.timeStep = scenario.timeStep.value_or(0.001);
  settings.integrator = run.integrator = scenario.integrator.value_or("rk4");
  run.trial.id = "figures";
  run.trial.source = path;
  run.trial.kind = "sim";
  // The rose drive uses the hemisphere's eight states (slots 4..11); the mass point comes from the curve.
  for (int i = physics::force_slot::body; i < 12; ++i) {
    if (scenario.initial[i] == 0.0) continue;
    char value[64];
    std::snprintf(value, sizeof value, "%.9g", scenario.initial[i]);
    run.start += (run.start.empty() ? "from " : ", ") + std::string(physics::kStateNames[i]) + " = " + value;
  }
  if (run.start.empty()) run.start = "upright at rest (the all-zero state)";
  RunSummary summary;
  try {
    summary = ScenarioRun(scenario, settings).run([&](const TrajectoryRow& row) {
      namespace slot = physics::force_slot;
      run.trial.time.push_back(row.time);
      run.trial.massX.push_back(row.state[slot::x_p]);
      run.trial.massY.push_back(row.state[slot::y_p]);
      run.trial.contactX.push_back(row.state[slot::u_a]);
      run.trial.contactY.push_back(row.state[slot::v_a]);
      run.trial.psi.push_back(row.state[slot::psi]);
    });
  } catch (const std::exception& e) {  // an unknown integrator named by the scenario
    std::cerr << "hemiroll figures: " << path << ": " << e.what() << "\n";
    return kExitUsage;
  }
  if (summary.event != physics::DomainEvent::None) run.event = physics::domainEventName(summary.event);

  const analysis::TrialFeatures features = analysis::analyzeTrial(run.trial.samples());
  const OutputFiles files = paperFigures(run, features);
  try {
    writeOutputFiles(*outDir, files);
  } catch (const record::RecordError& e) {
    std::cerr << "hemiroll figures: " << e.what() << "\n";
    return kExitFailure;
  }
  std::cout << paperFiguresMarkdown(run, features);
  std::cerr << "hemiroll figures: " << files.size() << " files written to " << *outDir << "\n";
  return kExitOk;
}

}  // namespace hemiroll::game
