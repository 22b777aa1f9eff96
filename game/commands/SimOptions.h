#pragma once
// The flags of `hemiroll sim`, parsed and checked, before any file is read.

#include <optional>
#include <string>
#include <vector>

namespace hemiroll::game {

struct SimOptions {
  std::string scenarioPath;
  std::optional<double> duration;          // --duration [s]; else the scenario's, else kDefaultDuration
  std::optional<double> timeStep;          // --dt [s]; else the scenario's, else kDefaultTimeStep
  std::optional<std::string> integrator;   // --integrator; else the scenario's, else kDefaultIntegrator
  std::optional<double> tolerance;         // --tol: adaptive integrators only; else the scenario's, else kDefaultTolerance
  std::optional<std::string> orientation;  // --orientation angles|quaternion; else the scenario's, else angles
  long long every = 1;                     // --every: a row every N steps
  long long maxRows = kDefaultMaxRows;     // --max-rows: refuse a run that would write more
  std::optional<std::string> outPath;      // --out; stdout when absent
  bool help = false;                       // --help
  bool listIntegrators = false;            // --integrator list

  static constexpr double kDefaultDuration = 10.0;  // [s]
  static constexpr double kDefaultTimeStep = 1e-3;  // [s], the paper's RK4 step
  static constexpr const char* kDefaultIntegrator = "rk4";
  static constexpr double kDefaultTolerance = 1e-8;  // [-], AdaptiveIntegrator<N>::kDefaultTolerance
  // About 3 GB of CSV: a run asking for more is told before it writes a row.
  static constexpr long long kDefaultMaxRows = 10'000'000;
};

struct SimOptionsResult {
  SimOptions options;
  std::string error;  // empty when the flags are good
};

// Parses the arguments after "sim". Accepts "--flag value" and "--flag=value".
SimOptionsResult parseSimOptions(const std::vector<std::string>& args);

const char* simUsage();

}  // namespace hemiroll::game
