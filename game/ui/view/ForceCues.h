#pragma once
// The coupling force made readable at a glance for a player who cannot feel
// it (issue 26): a ring round the proxy, a tone, a rumble. One number drives
// them all, the strain: the force over the mass point's weight m_p g, in
// [0, 1]. Why the weight: holding the mass point on a face tilted by theta
// takes about m_p g sin(theta) in the face's plane, so a strain of 0.1 is
// the pull of a face tilted about 6 degrees, and 1 is the hand pulling as
// hard as the whole weight (the cue saturates there; the paper's body:
// m_p = 1 kg, 9.81 N, beyond a desk device's 3 N).

#include <array>

namespace hemiroll::game {

// |F| / (m_p g) clamped to [0, 1]; 0 for a NaN force or a weight that is
// not a positive number, 1 for an infinite force.
double couplingStrain(double forceNewtons, double pointMass, double gravity);

// The ring drawn round the proxy: its radius grows with the square root of
// the strain (its area with the force, so small forces show), from
// kRingMinRadii to kRingMaxRadii hemisphere radii; its colour runs from
// calm blue (no force) through green (0.075) and yellow (0.15) to red (0.4
// and more: a face tilted over 20 degrees' worth of pull), saturated all
// the way.
inline constexpr double kRingMinRadii = 0.22;  // clear of the mass point (0.12 R) it surrounds when calm
inline constexpr double kRingMaxRadii = 0.7;
struct StrainRing {
  double radius = 0.0;                    // [m]
  std::array<float, 4> colour{};          // rgba
};
StrainRing strainRing(double strain, double hemisphereRadius);

// The tone's pitch for a strain [Hz]: 180 Hz at none, two octaves up (720 Hz)
// at full strain, on a log scale (equal steps of strain, equal intervals).
double strainPitch(double strain);

// The rumble's strength for a strain, in [0, limit]: proportional, limited
// (a gamepad's motors at full are a buzz, not information).
double strainRumble(double strain, double limit = 0.6);

}  // namespace hemiroll::game
