#pragma once
// The study's results and what is written from them: peers.csv, the gnuplot
// script of error against cost, docs/PEERS.md, and the smoke checks of the
// quick run. Owns: matching at equal cost and equal error, the reach table.
// Must not know any engine's API.

#include <string>
#include <vector>

#include "tools/peers/PeerEngine.h"

namespace hemiroll::tools::peers {

struct ScoredRun {
  RunResult run;
  RunScore score;
};

struct SceneStudy {
  PeerScene scene;
  std::vector<Sample> reference;
  double referenceDisagreement = 0.0;  // max contact-point distance from a reference at tol 1e-13 [m]
  std::vector<ScoredRun> runs;
};

struct EngineInfo {
  std::string name, version;
  std::vector<PeerSetting> settings;
};

struct Study {
  std::vector<EngineInfo> engines;
  std::vector<SceneStudy> scenes;
};

// One curve of the error-cost plot: a method or an engine at one setting, its
// points ordered by cost.
struct Curve {
  std::string engine, setting;
  std::vector<const ScoredRun*> points;
};
std::vector<Curve> curvesOf(const SceneStudy& scene);

// Queries the CSV, the checks and the markdown share.
std::string fmt(const char* format, double value);  // "-" for a non-finite value
std::string stepLabel(const RunResult& r);           // "h 1 ms" or "tol 1e-08"
const ScoredRun* find(const SceneStudy& s, const std::string& engine, const std::string& setting, double step);
// The engine's setting with the smallest error it reaches on the scene.
const Curve* bestCurve(const std::vector<Curve>& curves, const std::string& engine);
// The cheapest run of a curve within `target` of contact-point error.
const ScoredRun* cheapestWithin(const Curve& c, double target);
const ScoredRun* mostAccurate(const Curve& c);

// log-log interpolation along a curve; NaN outside its range.
double errorAtCost(const Curve& c, double cpuPerSimSecond);
double costAtError(const Curve& c, double contactError);

// Writes DIR/peers.csv, DIR/peers.gp and (if docPath is not empty) the report.
bool writeStudy(const Study& study, const std::string& dir, const std::string& docPath, std::string& error);

// The quick run's checks; each failure is one line.
std::vector<std::string> smokeCheck(const Study& study);

}  // namespace hemiroll::tools::peers
