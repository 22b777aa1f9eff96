#pragma once
// Physical parameters of the rolling system, with the paper's values
// (Sec. 4) as defaults. All SI.

#include <optional>
#include <string>

#include "engine/physics/FieldError.h"

namespace hemiroll::physics {

struct HemisphereParams {
  double radius = 0.04;     // R [m]
  double shellMass = 0.1;   // m_s, the homogeneous hemisphere [kg]
  double pointMass = 1.0;   // m_p, the driven mass point [kg]
  double gravity = 9.81;    // g [m/s^2], acting along -z of the base frame
};

// Nothing when the parameters describe a physical system; otherwise the
// first offending field ("params.m_p") and what is wrong with it. The
// prescribed drive accepts m_p = 0 (a bare hemisphere); the force-driven
// model needs m_p > 0 because the force accelerates the mass point.
std::optional<FieldError> paramsError(const HemisphereParams& params, bool allowZeroPointMass);
// The same as one sentence naming the field; empty when valid.
std::string validateParams(const HemisphereParams& params, bool allowZeroPointMass);

// Quantities derived once from the parameters, used on every evaluation.
struct ModelConstants {
  explicit ModelConstants(const HemisphereParams& params);

  HemisphereParams params;
  double comDepth;       // 3R/8: centre of mass below the face centre [m]
  double shellMoment;    // m_s R^2 [kg m^2], the scale of J_c
  double faceInertia;    // (2/5) m_s R^2, isotropic inertia about the face centre
};

}  // namespace hemiroll::physics
