#include "engine/physics/HemisphereParams.h"

#include <cmath>

namespace hemiroll::physics {

namespace {
bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }
}  // namespace

std::optional<FieldError> paramsError(const HemisphereParams& params, bool allowZeroPointMass) {
  if (!positiveFinite(params.radius)) return FieldError{"params.R", "(radius) must be a positive finite number of metres"};
  if (!positiveFinite(params.shellMass))
    return FieldError{"params.m_s", "(hemisphere mass) must be a positive finite number of kilograms"};
  if (!std::isfinite(params.pointMass) || params.pointMass < 0.0)
    return FieldError{"params.m_p", "(mass point) must be a finite, non-negative number of kilograms"};
  if (!allowZeroPointMass && params.pointMass == 0.0)
    return FieldError{"params.m_p", "(mass point) must be positive for a force-driven model"};
  if (!std::isfinite(params.gravity) || params.gravity < 0.0)
    return FieldError{"params.g", "(gravity) must be a finite, non-negative acceleration in m/s^2"};
  return std::nullopt;
}

std::string validateParams(const HemisphereParams& params, bool allowZeroPointMass) {
  const auto error = paramsError(params, allowZeroPointMass);
  return error ? error->sentence() : std::string();
}

ModelConstants::ModelConstants(const HemisphereParams& p)
    : params(p),
      comDepth(3.0 * p.radius / 8.0),
      shellMoment(p.shellMass * p.radius * p.radius),
      faceInertia(0.4 * p.shellMass * p.radius * p.radius) {}

}  // namespace hemiroll::physics
