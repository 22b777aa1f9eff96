#pragma once
// Everything the renderer draws in one frame, as plain data in SI units.
// The caller (the game) fills it from a ServoSnapshot and the level; the
// renderer knows neither. Keep one RenderScene and refill it every frame:
// the vectors keep their capacity, so a warm frame allocates nothing.
//
// Frames: the base frame is the plane's, z up, origin where the level's
// contact point starts (u_a = v_a = 0). The body frame sits at the centre of
// the flat face, z along the face normal; the curved part of the hemisphere
// is at body z < 0 (docs/PHYSICS.md).
//
// Bad numbers: the renderer never trusts these values. A non-finite pose
// keeps the last good one; a non-finite marker is skipped (SceneSanitizer).

#include <array>
#include <cstdint>
#include <vector>

namespace hemiroll::render {

class ContactTrace;

using Vec2d = std::array<double, 2>;
using Vec3d = std::array<double, 3>;
using Mat3d = std::array<double, 9>;  // row-major

enum class CameraMode : std::uint8_t {
  Follow,  // behind and above the hemisphere, fixed heading (no motion sickness from spin)
  Orbit,   // around the hemisphere by yaw/pitch (the game turns it with the arrow keys)
  Top,     // straight down: the plane as a map, for targets and the trace
};

struct CameraDef {
  CameraMode mode = CameraMode::Follow;
  double zoom = 1.0;         // > 0; 2 = twice as close
  double yaw = -0.6;         // orbit: heading of the eye around the focus [rad]
  double pitch = 0.55;       // orbit: elevation above the plane [rad], (0, pi/2)
  double fovY = 0.7;         // vertical field of view [rad]
};

// A target for the contact point on the plane. The judge tests each
// component on its own, so the tolerance region is a box of half-widths
// (halfWidthX, halfWidthY), drawn as such (a disc would misstate the corners).
struct TargetMarker {
  Vec2d position{};          // (u_a, v_a) target [m]
  Vec2d halfWidth{};         // tolerances [m]; a free component: a large value (clipped to the floor)
  bool inside = false;       // the contact point is within the band now (drawn brighter)
};

// A forbidden region of the plane (the contact point must not enter).
struct ZoneMarker {
  bool circle = true;
  Vec2d centre{};            // circle [m]
  double radius = 0.0;       // circle [m]
  Vec2d min{}, max{};        // box corners [m]
};

// A ghost: another run of the same level (the player's best, replayed in
// step with this one), drawn translucent so the two can be raced.
struct GhostPose {
  bool shown = false;
  Vec3d centre{0.0, 0.0, 0.04};              // [m], as RenderScene's
  Mat3d orientation{1, 0, 0, 0, 1, 0, 0, 0, 1};
  Vec2d massPoint{};                         // face coordinates [m]
};

struct RenderScene {
  // The hemisphere.
  double radius = 0.04;                      // R [m]
  Vec3d centre{0.0, 0.0, 0.04};              // sphere centre = face centre, base frame [m]
  Mat3d orientation{1, 0, 0, 0, 1, 0, 0, 0, 1};  // R of eq. (6): body -> base
  Vec2d massPoint{};                         // (x_p, y_p), face coordinates [m]

  // The haptic side.
  bool showProxy = false;
  Vec3d proxyPosition{};                     // base frame [m]
  bool springOn = false;                     // coupling engaged: the spring is drawn
  Vec3d force{};                             // force on the mass point, base frame [N]
  double forceScale = 0.01;                  // arrow length per newton [m/N]
  // A flat ring round the proxy on its horizontal plane, seen through
  // everything (the game's strain ring: its size and colour follow the
  // coupling force, game/ui/view/ForceCues.h). Drawn only with the proxy.
  bool showProxyRing = false;
  double proxyRingRadius = 0.0;              // outer radius [m]
  std::array<float, 4> proxyRingColour{};    // rgba

  // The task.
  std::vector<TargetMarker> targets;
  std::vector<ZoneMarker> forbidden;
  const ContactTrace* trace = nullptr;       // the contact point's path; null = none
  std::vector<Vec2d> examplePath;            // a way to go the level draws on the plane [m]
  double time = 0.0;                         // now [s], for the trace's fading

  GhostPose ghost;                           // same radius as the hemisphere

  // The autopilot's hint: where it would put the proxy now, drawn as a small
  // marker there and an arrow from the proxy to it. Moves nothing.
  bool showHint = false;
  Vec3d hintFrom{}, hintTo{};                // base frame [m]

  CameraDef camera;
};

}  // namespace hemiroll::render
