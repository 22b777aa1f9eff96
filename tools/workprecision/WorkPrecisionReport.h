#pragma once
// Results of the work-precision study and what is made of them: the CSV, the
// gnuplot script for the PNG, and docs/WORK_PRECISION.md.

#include <string>
#include <vector>

namespace hemiroll::tools {

struct WorkPoint {
  std::string scenario;
  std::string method;
  bool ours = true;
  std::string parameter;  // "h" or "tol"
  double value = 0.0;     // the step [s] or the tolerance [-]
  double error = 0.0;     // max_i |x_i(T) - x_ref,i(T)| [SI of each slot]
  double seconds = 0.0;   // median CPU time of one run [s]
  long long evaluations = 0;
  bool reliable = true;   // error well above the references' disagreement
};

struct ReferenceCheck {
  std::string scenario;
  double horizon = 0.0;
  double disagreement = 0.0;  // |ref(tol 1e-14) - ref(tol 1e-13)|, max norm
  double seconds = 0.0;
};

struct DriftRow {
  std::string method;
  double step = 0.0;
  double hours = 0.0;
  double maxDeviation = 0.0;  // max |H(t) - H(0)| [J]
  double firstHourTenth = 0.0;  // max |H - H0| over the first 6 minutes [J]
  double finalDeviation = 0.0;  // H(T) - H(0) [J]
  double slopePerHour = 0.0;  // least-squares slope of H - H0 [J/h]
  double seconds = 0.0;
  double invariant0 = 0.0;  // H(0) [J]
};

// log-log interpolation of a method's curve at error level e: the least CPU
// time among the segments that bracket e (a curve may fold back), and the
// evaluations on that segment; both < 0 if none.
struct CostAtError {
  double seconds = -1.0;
  double evaluations = -1.0;
};
CostAtError costAtError(const std::vector<WorkPoint>& curve, double e);
double timeAtError(const std::vector<WorkPoint>& curve, double e);

void writeCsv(const std::string& path, const std::vector<WorkPoint>& points);
void writeDriftCsv(const std::string& path, const std::vector<DriftRow>& rows);
void writeGnuplot(const std::string& scriptPath, const std::string& csvPath, const std::string& pngPath,
                  const std::vector<std::string>& scenarios, const std::vector<WorkPoint>& points);
void writeMarkdown(const std::string& path, const std::vector<WorkPoint>& points,
                   const std::vector<ReferenceCheck>& references, const std::vector<DriftRow>& drift, bool quick);

}  // namespace hemiroll::tools
