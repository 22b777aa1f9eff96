#pragma once
// Haptic guidance, the motor-learning condition: on top of the model's
// coupling force the device adds a spring-damper between the proxy and a
// planned proxy motion (the autopilot's, published by whoever plans). It
// pulls the hand along the plan ("autopilot" guidance) or pushes it away
// from the plan (error augmentation). The servo loop adds it to the
// coupling's device force before the safety layer, so the clamp, the rate
// limit, the engagement ramp and the watchdogs act on the sum: guidance can
// never take the device past its limit, and it ramps in and out with the
// coupling.
//
//   autopilot:           F = s (k e + c de),            e = p_plan - p_proxy
//   error augmentation:  F = s (-k e + c de),           (the spring pushes away)
// with |e| clipped at maxError (beyond it the spring stops growing), s the
// trial's fade value in [0, 1], all in the scene frame.
//
// A plan older than kStaleAfter gives no force (a planner that stopped must
// not hold the hand on its last wish); between samples the plan is
// extrapolated along its velocity for at most kMaxExtrapolation.

#include <array>
#include <cstdint>
#include <string>

#include "engine/haptics/DeviceSpec.h"
#include "engine/haptics/HapticDevice.h"
#include "engine/physics/ForceCoupling.h"

namespace hemiroll::haptics {

enum class GuidanceKind : std::uint8_t { None = 0, Autopilot = 1, ErrorAugmentation = 2 };

struct GuidanceDef {
  GuidanceKind kind = GuidanceKind::None;
  double stiffness = 0.0;  // k [N/m] >= 0: towards the plan (autopilot), away from it (error augmentation)
  double damping = 0.0;    // c [N s/m] >= 0: towards the plan's velocity, both kinds
  double scale = 1.0;      // s [-] in [0, 1]: the trial's fade value
  double maxError = 0.02;  // [m] > 0: the spring's reach; |e| beyond it counts as maxError

  bool active() const { return kind != GuidanceKind::None && scale > 0.0; }
};

// "none", "autopilot", "error_augmentation" (the protocol's names).
const char* guidanceKindName(GuidanceKind kind);
bool parseGuidanceKind(const std::string& name, GuidanceKind& kind);
// Empty when `def` is usable, else what is wrong (naming the field): gains
// within physics::kMaxStiffness and kMaxDamping (the bounds of every gain,
// wherever given).
std::string validateGuidance(const GuidanceDef& def);
// validateGuidance, and for a device with force output a spring it renders
// stably: at most its maxStiffness, as a coupling must be.
std::string guidanceProblem(const GuidanceDef& def, const DeviceSpec& device);

// One sample of the plan: where the planner wants the proxy at `time`.
// Plain arrays: it crosses threads as bytes (TripleBuffer).
struct GuideSample {
  double time = 0.0;                     // simulation time the plan answers [s]
  std::array<double, 3> position{};      // scene [m]
  std::array<double, 3> velocity{};      // scene [m/s]
  bool valid = false;                    // false: no plan (the planner gave up or has not started)
};

inline constexpr double kGuideStaleAfter = 0.05;        // [s] of simulation time
inline constexpr double kGuideMaxExtrapolation = 0.02;  // [s]

// The guidance force on the device, scene frame [N], at simulation time `t`
// for a proxy at (position, velocity). Zero for an inactive def, an invalid
// or stale sample. Allocation free.
Vec3 guidanceForce(const GuidanceDef& def, const GuideSample& plan, double t, const Vec3& proxyPosition,
                   const Vec3& proxyVelocity);

}  // namespace hemiroll::haptics
