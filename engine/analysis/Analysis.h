#pragma once
// engine/analysis: movement analysis of sampled trajectories, after Svinin
// et al. 2009, Sec. 4.2 and 5: the phases of a trial (acceleration, steady
// precession, deceleration/stabilisation) from psi(t), the rose the mass
// point draws on the face (leaves per revolution, leaf and outer radius, time
// span) and the helix the contact point draws on the plane (the arc's
// curvature, the loops along it, the drift). Definitions, estimators and
// their accuracy: docs/ANALYSIS.md.
//
// Owns: pure algorithms on plain columns (std::span<const double> of time
// and SI quantities): even resampling with gap and NaN handling, centred
// filters, the dominant tone of a signal, circle fitting, extrema with
// hysteresis, and the three detectors with their "not found: why" answers.
// Every result is finite: short, empty, constant or NaN-holding input gives
// found = false and a reason, never NaN or an exception.
// Must not know: files and formats (CSV, JSON, SVG), Lua, levels, the game,
// engine/record's or engine/haptics' types, the physics model. Depends on
// the standard library only (Eigen is allowed, not needed so far).
//
// Usage:
//   analysis::TrialSamples s{time, x_p, y_p, u_a, v_a, psi};  // spans of equal length
//   analysis::TrialFeatures f = analysis::analyzeTrial(s);
//   if (f.rose.found) use(f.rose.leaves, f.rose.leafRadius.value, f.rose.outerRadius.value);
//   else report(f.rose.reason);

#include "engine/analysis/CircleFit.h"
#include "engine/analysis/DominantTone.h"
#include "engine/analysis/Extrema.h"
#include "engine/analysis/Filters.h"
#include "engine/analysis/HelixDetector.h"
#include "engine/analysis/PhaseSegmenter.h"
#include "engine/analysis/RoseDetector.h"
#include "engine/analysis/Statistics.h"
#include "engine/analysis/TrialAnalyzer.h"
#include "engine/analysis/UniformSeries.h"
#include "engine/analysis/Wording.h"
