#pragma once
// One trial's features: phases from psi(t), then the rose on the mass
// point's path and the helix on the contact trace, each over the steady
// precession phase first (the paper's rose and helix are features of that
// phase: Sec. 5, "we will be interested in capturing only the precession
// phase"). Where there is no steady phase, or the feature is not found in
// it, the feature is looked for over the whole trial instead and its note
// says so (a rose may well outlast a precession rate that wanders).

#include <span>
#include <string>

#include "engine/analysis/HelixDetector.h"
#include "engine/analysis/PhaseSegmenter.h"
#include "engine/analysis/RoseDetector.h"

namespace hemiroll::analysis {

// The samples of one trial, as plain columns of equal length (SI units).
struct TrialSamples {
  std::span<const double> time;    // [s]
  std::span<const double> massX;   // x_p [m], face
  std::span<const double> massY;   // y_p [m], face
  std::span<const double> contactX;  // u_a [m], plane
  std::span<const double> contactY;  // v_a [m], plane
  std::span<const double> psi;     // [rad]
};

struct TrialAnalysisDef {
  PhaseDef phases;
  RoseDef rose;
  HelixDef helix;
};

struct TrialFeatures {
  Phases phases;
  RoseFeatures rose;
  TimeInterval roseWindow;         // where the rose was looked for
  std::string roseNote;            // non-empty when that is not the steady phase, and why
  HelixFeatures helix;
  TimeInterval helixWindow;
  std::string helixNote;
  // Loops of the trace per leaf of the rose (leaf period / loop spacing; the
  // paper's conjecture: one leaf, one loop); 0 unless both were found in the
  // same window.
  double loopsPerLeaf = 0.0;
};

TrialFeatures analyzeTrial(const TrialSamples& samples, const TrialAnalysisDef& def = {});

}  // namespace hemiroll::analysis
