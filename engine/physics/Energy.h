#pragma once
// Mechanical energy of hemisphere and mass point, and the power of the
// external force, for the exact checks of physics-notes.md:
//   free motion conserves E = T + V; any drive obeys dE/dt = F . v_p.

#include "engine/physics/RollingDynamics.h"

namespace hemiroll::physics {

struct EnergyTerms {
  double kinetic;    // T [J]
  double potential;  // V = g (m_s z_s + m_p z_p), heights above the plane [J]
  double total() const { return kinetic + potential; }
};

// State given as the 12-state vector (use PrescribedDriveSystem::fullState for
// the 8-state drive).
EnergyTerms mechanicalEnergy(const RollingDynamics& dynamics, const StateVector<12>& x);

// F . v_p for a force F on the mass point (base frame) [W].
double externalPower(const RollingDynamics& dynamics, const StateVector<12>& x, const Vec3& force);

}  // namespace hemiroll::physics
