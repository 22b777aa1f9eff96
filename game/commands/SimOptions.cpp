#include "game/commands/SimOptions.h"

#include <limits>

#include "engine/physics/IntegratorRegistry.h"
#include "engine/physics/RotationDrivenSystem.h"
#include "game/cli/ArgumentReader.h"

namespace hemiroll::game {

namespace {

std::string integratorNames() {
  std::string out;
  for (const auto& info : physics::IntegratorRegistry::builtin().list()) out += (out.empty() ? "" : ", ") + info.name;
  return out;
}

}  // namespace

const char* simUsage() {
  return "usage: hemiroll sim SCENARIO.lua [--duration S] [--dt S] [--integrator NAME] [--tol TOL] [--every N]\n"
         "                    [--orientation angles|quaternion] [--out FILE.csv] [--max-rows N]\n"
         "       hemiroll sim --integrator list\n"
         "\n"
         "Runs the physics of a scenario file (docs/SCENARIOS.md) headless and writes the\n"
         "trajectory as CSV (to stdout unless --out is given).\n"
         "\n"
         "  --duration S       simulated time [s] (default: the scenario's, else 10)\n"
         "  --dt S             integrator step [s] (default: the scenario's, else 0.001)\n"
         "  --integrator NAME  integration method (default: the scenario's, else rk4);\n"
         "                     'list' prints the available ones\n"
         "  --tol TOL          adaptive integrators (dopri5, dop853, dop853ld): error\n"
         "                     tolerance (1e-15 .. 1) per step, absolute and relative per component\n"
         "                     (default: the scenario's 'tol', else 1e-8); they choose\n"
         "                     their own steps and --dt only sets the output grid,\n"
         "                     filled in by dense output\n"
         "  --orientation F    free and proxy drives: integrate the orientation as the\n"
         "                     paper's contact angles ('angles', 12 states, default) or\n"
         "                     as a quaternion ('quaternion', 13 states, no trigonometry\n"
         "                     per evaluation); the CSV is the same\n"
         "  --every N          write a row every N steps (default 1); the first and last\n"
         "                     states are always written\n"
         "  --out FILE.csv     write the CSV to FILE instead of stdout\n"
         "  --max-rows N       refuse, before writing, a run that would write more rows\n"
         "                     (default 10000000, about 3 GB)\n"
         "  --help             print this help\n"
         "\n"
         "Exit codes: 0 done (also when a domain event stops the run early),\n"
         "1 output could not be written, 2 bad flags or bad scenario.\n";
}

SimOptionsResult parseSimOptions(const std::vector<std::string>& args) {
  SimOptionsResult result;
  SimOptions& o = result.options;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .positional("scenario file", 1, [&](const std::string& path) { o.scenarioPath = path; })
      .option("--duration", cli::positiveNumber(o.duration, "a positive number of seconds"))
      .option("--dt", cli::positiveNumber(o.timeStep, "a positive number of seconds"))
      // Below 1e-15 no double step can meet it: the run would only report a
      // non-finite step (1e-300 did, with exit 0).
      .option("--tol", cli::numberIn(o.tolerance, 1e-15, 1.0, "a tolerance in 1e-15 .. 1"))
      .option("--every", cli::integerIn(o.every, 1, std::numeric_limits<long long>::max(), "a whole number >= 1"))
      .option("--max-rows", cli::integerIn(o.maxRows, 2, std::numeric_limits<long long>::max(), "a whole number >= 2"))
      .option("--out", cli::text(o.outPath, "a file name"))
      .option("--orientation",
              [&](const std::string& flag, const std::string& value) {
                physics::OrientationForm form;
                if (!physics::parseOrientationForm(value, form)) return cli::needs(flag, "'angles' or 'quaternion'", value);
                o.orientation = value;
                return std::string();
              })
      .option("--integrator", [&](const std::string&, const std::string& value) {
        if (value == "list") {
          o.listIntegrators = true;
        } else if (!physics::IntegratorRegistry::builtin().contains(value)) {
          return "unknown integrator '" + value + "' (available: " + integratorNames() + ")";
        } else {
          o.integrator = value;
        }
        return std::string();
      });
  result.error = reader.read(args);
  if (result.error.empty() && !o.help && !o.listIntegrators && o.scenarioPath.empty())
    result.error = "missing the scenario file";
  return result;
}

}  // namespace hemiroll::game
