#pragma once
// The procedural hemisphere in its body frame (Orientation.h): the flat face
// is the z = 0 disc, the curved shell the lower half, z in [-R, 0].
// Smooth normals (the sphere's radial direction; +z on the face).
//
// Markings, so that rolling and spin are visible from any camera:
// - the shell in meridian stripes (alternating shades), one of them red:
//   the sector around body +x;
// - on the face, a dark ring at 0.6 R and a red stripe from the centre along
//   body +x (the face's "heading"; psi turns it).
// The colours are exported for tests that look for them on screen.

#include "engine/render/MeshData.h"

namespace hemiroll::render {

struct HemisphereMeshDef {
  double radius = 1.0;       // [m]; the renderer uses 1 and scales
  int segments = 48;         // around the axis; a multiple of `stripes`
  int rings = 16;            // from the rim to the pole
  int stripes = 8;           // meridian stripes on the shell
};

inline constexpr Rgba kShellLight{0.92f, 0.90f, 0.84f, 1.0f};
inline constexpr Rgba kShellDark{0.30f, 0.42f, 0.62f, 1.0f};
inline constexpr Rgba kMarkRed{0.85f, 0.12f, 0.10f, 1.0f};
inline constexpr Rgba kFace{0.96f, 0.95f, 0.90f, 1.0f};
inline constexpr Rgba kFaceRing{0.15f, 0.17f, 0.22f, 1.0f};
inline constexpr double kFaceRingRadius = 0.6;      // [R], centre of the ring band
inline constexpr double kFaceRingHalfWidth = 0.05;  // [R]
inline constexpr double kFaceStripeHalfAngle = 0.12;  // [rad] either side of body +x

MeshData makeHemisphereMesh(const HemisphereMeshDef& def = {});

}  // namespace hemiroll::render
