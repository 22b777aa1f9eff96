#pragma once
// Small procedural meshes the renderer places with a model matrix: unit
// sizes, one colour each (the shader tints them per draw).

#include "engine/render/MeshData.h"

namespace hemiroll::render {

// Unit sphere, smooth normals.
MeshData makeSphereMesh(int segments = 24, int rings = 12, Rgba color = {1, 1, 1, 1});
// An arrow from the origin to (0, 0, 1): shaft radius 0.035, cone head of
// length 0.25 and radius 0.09 (proportions that stay readable at any length
// once scaled uniformly in x and y by the caller's thickness).
MeshData makeArrowMesh(int segments = 16, Rgba color = {1, 1, 1, 1});
// A flat disc of radius 1 in the z = 0 plane: `centre` colour in the middle
// fading linearly to `rim` at the edge (the blurred contact shadow).
MeshData makeDiscMesh(int segments, Rgba centre, Rgba rim);
// The octahedron marker for the haptic proxy when no mesh file is found.
MeshData makeOctahedronMesh(Rgba color = {1, 1, 1, 1});
// The square [-1, 1]^2 at z = 0, normal +z.
MeshData makeQuadMesh(Rgba color = {1, 1, 1, 1});

}  // namespace hemiroll::render
