#include "engine/render/PrimitiveMeshes.h"

#include <cmath>

namespace hemiroll::render {

namespace {

void addTriangle(MeshData& m, const Vertex& a, const Vertex& b, const Vertex& c) {
  m.vertices.insert(m.vertices.end(), {a, b, c});
}

Vertex spherePoint(double phi, double theta, Rgba c) {
  const double x = std::sin(theta) * std::cos(phi), y = std::sin(theta) * std::sin(phi), z = std::cos(theta);
  return makeVertex(float(x), float(y), float(z), float(x), float(y), float(z), c);
}

}  // namespace

MeshData makeSphereMesh(int segments, int rings, Rgba c) {
  MeshData m;
  for (int j = 0; j < segments; ++j) {
    const double p0 = 2.0 * M_PI * j / segments, p1 = 2.0 * M_PI * (j + 1) / segments;
    for (int i = 0; i < rings; ++i) {
      const double t0 = M_PI * i / rings, t1 = M_PI * (i + 1) / rings;
      const Vertex a = spherePoint(p0, t0, c), b = spherePoint(p0, t1, c), d = spherePoint(p1, t1, c),
                   e = spherePoint(p1, t0, c);
      addTriangle(m, a, b, d);
      addTriangle(m, a, d, e);
    }
  }
  return m;
}

MeshData makeArrowMesh(int segments, Rgba c) {
  constexpr float kShaft = 0.035f, kHead = 0.09f, kHeadStart = 0.75f;
  MeshData m;
  for (int j = 0; j < segments; ++j) {
    const float p0 = float(2.0 * M_PI * j / segments), p1 = float(2.0 * M_PI * (j + 1) / segments);
    const float c0 = std::cos(p0), s0 = std::sin(p0), c1 = std::cos(p1), s1 = std::sin(p1);
    // Shaft side.
    const Vertex a = makeVertex(kShaft * c0, kShaft * s0, 0, c0, s0, 0, c);
    const Vertex b = makeVertex(kShaft * c1, kShaft * s1, 0, c1, s1, 0, c);
    const Vertex d = makeVertex(kShaft * c1, kShaft * s1, kHeadStart, c1, s1, 0, c);
    const Vertex e = makeVertex(kShaft * c0, kShaft * s0, kHeadStart, c0, s0, 0, c);
    addTriangle(m, a, b, d);
    addTriangle(m, a, d, e);
    // Head: cone side (normal tilted by the cone's slope) and its base.
    const float slope = kHead / (1.0f - kHeadStart), n = 1.0f / std::sqrt(1.0f + slope * slope);
    const Vertex h0 = makeVertex(kHead * c0, kHead * s0, kHeadStart, c0 * n, s0 * n, slope * n, c);
    const Vertex h1 = makeVertex(kHead * c1, kHead * s1, kHeadStart, c1 * n, s1 * n, slope * n, c);
    const float cm = std::cos((p0 + p1) / 2), sm = std::sin((p0 + p1) / 2);
    const Vertex tip = makeVertex(0, 0, 1, cm * n, sm * n, slope * n, c);
    addTriangle(m, h0, h1, tip);
    const Vertex base = makeVertex(0, 0, kHeadStart, 0, 0, -1, c);
    Vertex b0 = h0, b1 = h1;
    b0.normal[0] = b0.normal[1] = b1.normal[0] = b1.normal[1] = 0.0f;
    b0.normal[2] = b1.normal[2] = -1.0f;
    addTriangle(m, b1, b0, base);
  }
  return m;
}

MeshData makeDiscMesh(int segments, Rgba centre, Rgba rim) {
  MeshData m;
  const Vertex mid = makeVertex(0, 0, 0, 0, 0, 1, centre);
  for (int j = 0; j < segments; ++j) {
    const float p0 = float(2.0 * M_PI * j / segments), p1 = float(2.0 * M_PI * (j + 1) / segments);
    addTriangle(m, mid, makeVertex(std::cos(p0), std::sin(p0), 0, 0, 0, 1, rim),
                makeVertex(std::cos(p1), std::sin(p1), 0, 0, 0, 1, rim));
  }
  return m;
}

MeshData makeOctahedronMesh(Rgba c) {
  MeshData m;
  const float px[6][3] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int k = 0; k < 4; ++k) {
    const float* a = px[k];
    const float* b = px[(k + 1) % 4];
    for (int cap = 4; cap <= 5; ++cap) {
      const float* t = px[cap];
      float nx = a[0] + b[0] + t[0], ny = a[1] + b[1] + t[1], nz = a[2] + b[2] + t[2];
      const float len = std::sqrt(nx * nx + ny * ny + nz * nz);
      nx /= len, ny /= len, nz /= len;
      const Vertex va = makeVertex(a[0], a[1], a[2], nx, ny, nz, c), vb = makeVertex(b[0], b[1], b[2], nx, ny, nz, c),
                   vt = makeVertex(t[0], t[1], t[2], nx, ny, nz, c);
      if (cap == 4) addTriangle(m, va, vb, vt);
      else addTriangle(m, vb, va, vt);
    }
  }
  return m;
}

MeshData makeQuadMesh(Rgba c) {
  MeshData m;
  const Vertex a = makeVertex(-1, -1, 0, 0, 0, 1, c), b = makeVertex(1, -1, 0, 0, 0, 1, c),
               d = makeVertex(1, 1, 0, 0, 0, 1, c), e = makeVertex(-1, 1, 0, 0, 0, 1, c);
  m.vertices = {a, b, d, a, d, e};
  return m;
}

}  // namespace hemiroll::render
