#include "engine/render/HemisphereMesh.h"

#include <cmath>
#include <stdexcept>

namespace hemiroll::render {

namespace {

void addQuad(MeshData& m, const Vertex& a, const Vertex& b, const Vertex& c, const Vertex& d) {
  m.vertices.insert(m.vertices.end(), {a, b, c, a, c, d});
}

// A point on the sphere of radius r at azimuth phi and polar angle theta from
// the bottom pole (theta = 0 at the pole, pi/2 at the rim), normal radial.
Vertex shellVertex(double r, double phi, double theta, Rgba c) {
  const double s = std::sin(theta);
  const double x = s * std::cos(phi), y = s * std::sin(phi), z = -std::cos(theta);
  return makeVertex(float(r * x), float(r * y), float(r * z), float(x), float(y), float(z), c);
}

Vertex faceVertex(double r, double phi, Rgba c) {
  return makeVertex(float(r * std::cos(phi)), float(r * std::sin(phi)), 0.0f, 0.0f, 0.0f, 1.0f, c);
}

// Azimuth of a sector's middle, wrapped to (-pi, pi].
double wrap(double a) { return std::remainder(a, 2.0 * M_PI); }

}  // namespace

MeshData makeHemisphereMesh(const HemisphereMeshDef& def) {
  if (!(def.radius > 0.0) || def.segments < 8 || def.rings < 2 || def.stripes < 2 || def.segments % def.stripes != 0)
    throw std::invalid_argument("HemisphereMeshDef: radius > 0, segments >= 8, rings >= 2, stripes >= 2 dividing segments");
  MeshData m;
  m.primitive = Primitive::Triangles;
  const double r = def.radius;
  const int perStripe = def.segments / def.stripes;
  const double dPhi = 2.0 * M_PI / def.segments, dTheta = (M_PI / 2.0) / def.rings;
  // Stripes are centred on body +x: segment j spans [phi0 + j dPhi, ...].
  const double phi0 = -0.5 * perStripe * dPhi;

  for (int j = 0; j < def.segments; ++j) {
    const int stripe = j / perStripe;
    const Rgba c = stripe == 0 ? kMarkRed : (stripe % 2 ? kShellDark : kShellLight);
    const double p0 = phi0 + j * dPhi, p1 = p0 + dPhi;
    for (int i = 0; i < def.rings; ++i) {
      const double t0 = i * dTheta, t1 = t0 + dTheta;
      // Counter-clockwise seen from outside the shell.
      addQuad(m, shellVertex(r, p0, t0, c), shellVertex(r, p0, t1, c), shellVertex(r, p1, t1, c),
              shellVertex(r, p1, t0, c));
    }
  }

  // The face: annuli whose edges include the ring band's, so its edges are exact.
  const double edges[] = {0.0,
                          0.3,
                          kFaceRingRadius - kFaceRingHalfWidth,
                          kFaceRingRadius + kFaceRingHalfWidth,
                          0.8,
                          1.0};
  for (std::size_t k = 0; k + 1 < std::size(edges); ++k) {
    const double r0 = edges[k] * r, r1 = edges[k + 1] * r;
    const bool ring = k == 2;
    for (int j = 0; j < def.segments; ++j) {
      const double p0 = j * dPhi, p1 = p0 + dPhi;
      const bool stripe = std::abs(wrap(p0 + dPhi / 2.0)) < kFaceStripeHalfAngle;
      const Rgba c = ring ? kFaceRing : (stripe ? kMarkRed : kFace);
      // Counter-clockwise seen from above (+z).
      addQuad(m, faceVertex(r0, p0, c), faceVertex(r1, p0, c), faceVertex(r1, p1, c), faceVertex(r0, p1, c));
    }
  }
  return m;
}

}  // namespace hemiroll::render
