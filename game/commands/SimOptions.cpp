#include "game/commands/SimOptions.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "engine/physics/IntegratorRegistry.h"
#include "engine/physics/RotationDrivenSystem.h"

namespace hemiroll::game {

namespace {

// The whole text must be a finite number greater than zero.
bool parsePositive(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value) && value > 0.0;
}

bool parseCount(const std::string& text, long long& value) {
  if (text.empty() || text.front() == '-' || text.front() == '+') return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(text.c_str(), &end, 10);
  return errno == 0 && end == text.c_str() + text.size() && value >= 1;
}

std::string integratorNames() {
  std::string out;
  for (const auto& info : physics::IntegratorRegistry::builtin().list()) out += (out.empty() ? "" : ", ") + info.name;
  return out;
}

}  // namespace

const char* simUsage() {
  return "usage: hemiroll sim SCENARIO.lua [--duration S] [--dt S] [--integrator NAME] [--tol TOL] [--every N]\n"
         "                    [--orientation angles|quaternion] [--out FILE.csv]\n"
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
         "                     tolerance per step, absolute and relative per component\n"
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
         "  --help             print this help\n"
         "\n"
         "Exit codes: 0 done (also when a domain event stops the run early),\n"
         "1 output could not be written, 2 bad flags or bad scenario.\n";
}

SimOptionsResult parseSimOptions(const std::vector<std::string>& args) {
  SimOptionsResult result;
  SimOptions& o = result.options;
  auto fail = [&](const std::string& message) {
    result.error = message;
    return result;
  };

  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i];
    if (arg == "--help" || arg == "-h") {
      o.help = true;
      continue;
    }
    if (arg.rfind("-", 0) != 0 || arg == "-") {
      if (!o.scenarioPath.empty()) return fail("unexpected argument '" + arg + "' (only one scenario file)");
      o.scenarioPath = arg;
      continue;
    }
    std::optional<std::string> inlineValue;
    if (const auto eq = arg.find('='); eq != std::string::npos) {
      inlineValue = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
    }
    if (arg != "--duration" && arg != "--dt" && arg != "--integrator" && arg != "--every" && arg != "--out" &&
        arg != "--tol" && arg != "--orientation")
      return fail("unknown flag '" + arg + "'");
    std::string value;
    if (inlineValue) {
      value = *inlineValue;
    } else {
      if (i + 1 >= args.size()) return fail("flag " + arg + " needs a value");
      value = args[++i];
    }

    if (arg == "--duration" || arg == "--dt") {
      double number = 0.0;
      if (!parsePositive(value, number))
        return fail("flag " + arg + " needs a positive number of seconds, got '" + value + "'");
      (arg == "--duration" ? o.duration : o.timeStep) = number;
    } else if (arg == "--tol") {
      double number = 0.0;
      if (!parsePositive(value, number)) return fail("flag --tol needs a positive number, got '" + value + "'");
      o.tolerance = number;
    } else if (arg == "--orientation") {
      physics::OrientationForm form;
      if (!physics::parseOrientationForm(value, form))
        return fail("flag --orientation needs 'angles' or 'quaternion', got '" + value + "'");
      o.orientation = value;
    } else if (arg == "--every") {
      if (!parseCount(value, o.every)) return fail("flag --every needs a whole number >= 1, got '" + value + "'");
    } else if (arg == "--integrator") {
      if (value == "list") {
        o.listIntegrators = true;
      } else if (!physics::IntegratorRegistry::builtin().contains(value)) {
        return fail("unknown integrator '" + value + "' (available: " + integratorNames() + ")");
      } else {
        o.integrator = value;
      }
    } else {  // --out
      if (value.empty()) return fail("flag --out needs a file name");
      o.outPath = value;
    }
  }
  if (!o.help && !o.listIntegrators && o.scenarioPath.empty()) return fail("missing the scenario file");
  return result;
}

}  // namespace hemiroll::game
