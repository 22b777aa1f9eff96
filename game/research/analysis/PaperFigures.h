#pragma once
// The paper's Figs. 9, 10 and 11 (Svinin et al. 2009, Sec. 5) from a run of
// the 8-state prescribed rose drive, with what the analysis measures on
// that run beside the paper's numbers.

#include <string>

#include "engine/analysis/TrialAnalyzer.h"
#include "engine/physics/RoseDrive.h"
#include "game/research/analysis/AnalysisOutput.h"
#include "game/research/analysis/TrialData.h"

namespace hemiroll::game {

struct FigureRun {
  TrialData trial;                // the run's samples (id "figures")
  physics::RoseDef rose;          // r1, r2, k, Omega
  double timeStep = 0.001;        // [s]
  std::string integrator = "rk4";
  std::string event;              // a domain event that stopped the run early, else empty
  std::string start;              // the initial state in words ("upright at rest", "u_o = -0.58271 rad")
};

// fig09_mass_point_rose.svg, fig10_contact_trajectory.svg,
// fig11_precession_angle.svg, figures_features.json, figures_features.md.
OutputFiles paperFigures(const FigureRun& run, const analysis::TrialFeatures& features);

// The markdown summary (also figures_features.md).
std::string paperFiguresMarkdown(const FigureRun& run, const analysis::TrialFeatures& features);

}  // namespace hemiroll::game
