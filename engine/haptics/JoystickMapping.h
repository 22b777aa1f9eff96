#pragma once
// The pure arithmetic of a force-feedback joystick (SdlJoystickDevice), kept
// free of SDL so that it can be tested without one:
//   - stick axes -> device position [m]: a dead zone about the centre, the
//     rest rescaled so the output starts at zero (no jump at its edge), full
//     deflection = reach from the centre;
//   - force [N] -> an SDL constant-force effect: level 0..32767, reaching
//     32767 at the spec's maxForce and never beyond it; a direction in SDL's
//     cartesian encoding.
//
// Frames. SDL axes: x right positive, y positive towards the user (stick
// pulled back). Device/scene frame: x right, y away from the user, z up, so
// y = -axis. SDL_HapticDirection (cartesian) names where the force comes
// FROM (north = (0, -1) = away from the user): a force pushing the stick
// towards +y (away) comes from the south, (0, +1). Hence
//   dir = (-F_x, +F_y, 0) for a force F in the device frame.
// A stick has two force axes: the vertical force is not rendered.

#include <array>
#include <cstdint>

#include "engine/haptics/HapticDevice.h"

namespace hemiroll::haptics {

struct JoystickMappingDef {
  int axisX = 0, axisY = 1;  // SDL axis indices for x and y
  int axisZ = -1;            // axis for the height (a throttle, pushed forward = up), or -1: z = centre z
  double deadZone = 0.08;    // fraction of full deflection read as centred [-]; cheap sticks rest a few % off
  double reach = 0.05;       // full deflection -> this far from the centre [m]
  std::array<double, 3> centre{0.0, 0.0, 0.0};  // device position of the centred stick [m]
};

// What SDL_HapticConstant needs (direction type SDL_HAPTIC_CARTESIAN).
struct ConstantForceCommand {
  std::int16_t level = 0;                   // 0..32767
  std::array<std::int32_t, 3> direction{0, 1, 0};  // cartesian, where the force comes from
  bool operator==(const ConstantForceCommand&) const = default;
};

// Raw SDL axis value (-32768..32767) -> [-1, 1] with the dead zone applied.
double axisToUnit(std::int16_t raw, double deadZone);

// Raw axes (indexed by SDL axis number; missing axes read as centred) -> position.
Vec3 axesToPosition(const JoystickMappingDef& def, const std::int16_t* axes, int axisCount);

// Device-frame force -> effect; non-finite forces give level 0.
ConstantForceCommand forceToConstantEffect(const Vec3& force, double maxForce);

}  // namespace hemiroll::haptics
