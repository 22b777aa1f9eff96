#pragma once
// The plots of one analysed trial (game/research/report line plots): the contact
// point's trace on the plane (the paper's Figs. 6 and 10) with the arc and
// the loops found, the mass point's path on the face (Figs. 7 and 9) with
// the rose's leaf tips, the precession angle psi(t) (Fig. 11) with the
// phases shaded, its rate, the channels over time, and an overview sheet
// of all of them. Lengths are shown in cm, as in the paper.

#include <string>

#include "engine/analysis/TrialAnalyzer.h"
#include "game/research/analysis/TrialData.h"
#include "game/research/report/LinePlot.h"

namespace hemiroll::game {

report::LinePlotDef contactTracePlot(const TrialData& trial, const analysis::TrialFeatures& features);
report::LinePlotDef massPointPlot(const TrialData& trial, const analysis::TrialFeatures& features);
report::LinePlotDef precessionAnglePlot(const TrialData& trial, const analysis::TrialFeatures& features);
report::LinePlotDef precessionRatePlot(const analysis::TrialFeatures& features);
report::LinePlotDef channelsPlot(const TrialData& trial);
// All of the above on one page (3 x 2 panels).
std::string overviewSheet(const TrialData& trial, const analysis::TrialFeatures& features);

}  // namespace hemiroll::game
