#pragma once
// What haptic guidance did in a trial, from its recording: the work the
// guidance force did on the hand, and how much of the hand's force went
// against it. This is what separates what the device did from what the
// hand did (docs/ANALYSIS.md "Guidance").
//
//   work    W = integral of F_g . v dt        (trapezoid over the samples)
//           F_g the guidance force, v the proxy velocity (scene): W > 0 when
//           the guidance pushed the hand along, W < 0 when the hand moved
//           against it (error augmentation does negative work on a hand
//           that holds the course).
//   opposed share = integral of max(0, -F_h . g) dt / integral of |F_h| dt
//           over the samples where guidance acts (|F_g| > 0), g = F_g / |F_g|,
//           F_h the hand's force on the mass point: 0 when the hand never
//           pushed against the guidance, 1 when it pushed straight against it
//           all along.

#include <span>

namespace hemiroll::analysis {

struct GuidanceSamples {
  std::span<const double> time;                                  // [s]
  std::span<const double> guidanceX, guidanceY, guidanceZ;       // F_g [N], scene
  std::span<const double> proxyVelocityX, proxyVelocityY, proxyVelocityZ;  // v [m/s], scene
  std::span<const double> handForceX, handForceY, handForceZ;    // F_h [N], scene
};

struct GuidanceWork {
  bool present = false;      // some sample carries a guidance force
  double work = 0.0;         // W [J]
  double opposedShare = 0.0; // [0, 1]; 0 without guidance
  double guidedTime = 0.0;   // how long guidance acted [s]
};

GuidanceWork guidanceWork(const GuidanceSamples& samples);

}  // namespace hemiroll::analysis
