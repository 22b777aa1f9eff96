#pragma once
// A mesh on the CPU side: non-indexed vertices with position, normal and
// RGBA colour. One vertex layout for everything the renderer draws (lit
// solids, unlit lines and decals), so one shader program and one GpuMesh
// class serve all. Markings are per-triangle colours (crisp stripes).

#include <vector>

namespace hemiroll::render {

struct Vertex {
  float position[3];  // model frame [m] (or unit size, scaled by the model matrix)
  float normal[3];    // unit; ignored by unlit drawing
  float color[4];     // linear RGBA in [0, 1]
};

enum class Primitive { Triangles, Lines };

struct MeshData {
  Primitive primitive = Primitive::Triangles;
  std::vector<Vertex> vertices;
};

struct Rgba {
  float r, g, b, a;
};

inline Vertex makeVertex(float x, float y, float z, float nx, float ny, float nz, Rgba c) {
  return Vertex{{x, y, z}, {nx, ny, nz}, {c.r, c.g, c.b, c.a}};
}

}  // namespace hemiroll::render
