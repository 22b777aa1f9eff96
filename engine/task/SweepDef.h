#pragma once
// A parameter sweep of the paper's rose drive (docs/SWEEP.md) as plain data:
// the base run (parameters, rose, start, duration, step, integrator) and the
// axes, each a parameter with its values. The grid is the product of the
// axes; point 0 is every axis at its first value, and the LAST axis varies
// fastest (the order of nested loops written in the file's order).
// Expanding a point into a run is the game's (game/research/sweep/SweepGrid).

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/physics/HemisphereParams.h"
#include "engine/physics/RoseDrive.h"

namespace hemiroll::task {

// The parameters an axis may vary: the hemisphere's and the rose's.
enum class SweepParam { R, m_s, m_p, g, r1, r2, k, Omega };

struct SweepParamInfo {
  SweepParam param;
  const char* name;    // as written in the spec ("Omega")
  const char* column;  // CSV column with its SI unit ("Omega_rad_per_s")
  const char* label;   // for plot axes, with the unit ("Omega [rad/s]")
};

const std::array<SweepParamInfo, 8>& sweepParams();
const SweepParamInfo& sweepParamInfo(SweepParam param);
std::optional<SweepParam> findSweepParam(std::string_view name);

// The value of `param` in (params, rose), and setting it.
double sweepParamValue(SweepParam param, const physics::HemisphereParams& params, const physics::RoseDef& rose);
void setSweepParam(SweepParam param, double value, physics::HemisphereParams& params, physics::RoseDef& rose);

// Where the hemisphere starts (the mass point always starts at p(0) = (r1 + r2, 0)).
enum class SweepStart {
  Rest,         // upright at rest, the all-zero body state (levels/scenarios/rose_paper.lua)
  Equilibrium,  // at rest, tilted by the static tilt for p(0), computed per point (the paper's start)
};

const char* sweepStartName(SweepStart start);

struct SweepAxis {
  SweepParam param = SweepParam::k;
  std::vector<double> values;  // in the file's order (a range: from first to last)
  bool log = false;            // a range spaced geometrically, or values to show so: maps use log10
};

// How each point's run is judged (docs/SWEEP.md, "Metrics"). The first
// three are engine/analysis' PhaseDef (the steady precession), with its
// defaults, the same `hemiroll analyze` uses on people's trials.
struct SweepAnalysisDef {
  double minRate = 0.05;            // [rad/s] a slower steady rate is no precession
  double relativeBand = 0.25;       // [-] steady: the rate within this fraction of its median ...
  double absoluteBand = 0.02;       // [rad/s] ... plus this
  double minSteadyFraction = 0.8;   // [-] paper-like: the steady phase covers this share of the run
  double maxRelativeSpread = 0.25;  // [-] paper-like: spread of the steady rate / |its median| at most
};

struct SweepDef {
  std::string source;       // the file as named by the caller, for messages
  std::string description;  // free text
  physics::HemisphereParams params;  // base values (the paper's by default)
  physics::RoseDef rose;             // base r1, r2, k, Omega (the paper's by default)
  SweepStart start = SweepStart::Equilibrium;
  double duration = 35.0;            // [s] per point
  double timeStep = 0.001;           // [s]
  std::string integrator = "rk4";
  double tolerance = 1e-8;           // adaptive integrators only
  SweepAnalysisDef analysis;
  std::vector<SweepAxis> axes;       // at least one

  // The product of the axes' lengths.
  long long pointCount() const;
};

// Largest grid a spec may describe: a larger one is a typo (a count of 1e6).
inline constexpr long long kMaxSweepPoints = 1'000'000;

}  // namespace hemiroll::task
