#pragma once
// The per-frame geometry of a RenderScene that is not a fixed mesh: floor
// decals (target bands, forbidden zones), the fading contact trace, the
// target outlines and the spring coil. CPU only (no GL), so it is tested
// without a window. Every function appends to a caller-owned vector that
// keeps its capacity between frames: no allocation once warm.
//
// Decals lie on the plane (z = 0); the renderer draws them without depth
// test before the solids, so no z-offset is needed.

#include <vector>

#include "engine/render/ContactTrace.h"
#include "engine/render/MeshData.h"
#include "engine/render/RenderScene.h"

namespace hemiroll::render {

inline constexpr Rgba kTargetFill{0.10f, 0.65f, 0.25f, 0.35f};
inline constexpr Rgba kTargetFillInside{0.15f, 0.90f, 0.35f, 0.60f};
inline constexpr Rgba kTargetLine{0.05f, 0.45f, 0.15f, 1.0f};
inline constexpr Rgba kZoneFill{0.85f, 0.10f, 0.10f, 0.30f};
inline constexpr Rgba kZoneLine{0.70f, 0.05f, 0.05f, 1.0f};
inline constexpr Rgba kTraceColor{0.95f, 0.45f, 0.05f, 1.0f};  // alpha from the point's age
inline constexpr Rgba kSpringColor{0.15f, 0.35f, 0.85f, 1.0f};
inline constexpr Rgba kExamplePathColor{0.25f, 0.80f, 1.00f, 1.0f};  // cyan, the trace's complement: never mistaken for it

// Floor decals are clipped to [-extent, extent]^2 (a free component's band
// would otherwise be infinite).
void appendTargetFills(const RenderScene& scene, double extent, std::vector<Vertex>& out);
void appendZoneFills(const RenderScene& scene, std::vector<Vertex>& out);
// GL_LINES pairs.
void appendTargetOutlines(const RenderScene& scene, double extent, std::vector<Vertex>& out);
// Which way to go: an arrow on the floor from the contact point (under the
// sphere centre) to each target it is not yet inside, along the judged
// components only (a free component is not a direction to go).
void appendTargetPointers(const RenderScene& scene, std::vector<Vertex>& out);
void appendZoneOutlines(const RenderScene& scene, std::vector<Vertex>& out);
void appendTraceLines(const ContactTrace& trace, double now, std::vector<Vertex>& out);
// A level's example path, dashed (every other segment, so that a trace
// drawn along it stays visible), at most `maxVertices` vertices.
void appendExamplePath(const RenderScene& scene, std::size_t maxVertices, std::vector<Vertex>& out);
// A helix of `turns` turns and radius `coilRadius` from a to b [m].
void appendSpringCoil(const Vec3d& a, const Vec3d& b, double coilRadius, int turns, std::vector<Vertex>& out);
// A flat horizontal ring (triangles) round `centre`, from inner to outer
// radius [m], in `segments` pieces: 6 vertices each.
void appendFlatRing(const Vec3d& centre, double inner, double outer, int segments, Rgba colour, std::vector<Vertex>& out);
// Floor grid lines around the origin: every 10 cm (darker) within
// [-extent, extent]^2, every 1 cm (faint) within [-fineExtent, fineExtent]^2.
// Fine lines far from the hemisphere would only alias, and under a software
// rasteriser lines cost per pixel.
MeshData makeFloorGrid(double extent, double fineExtent);

inline constexpr int kCircleSegments = 48;

}  // namespace hemiroll::render
