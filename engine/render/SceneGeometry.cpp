#include "engine/render/SceneGeometry.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::render {

namespace {

Vertex flat(double x, double y, double z, Rgba c) { return makeVertex(float(x), float(y), float(z), 0, 0, 1, c); }

struct Box {
  double x0, y0, x1, y1;
};

Box targetBox(const TargetMarker& t, double extent) {
  return {std::max(-extent, t.position[0] - t.halfWidth[0]), std::max(-extent, t.position[1] - t.halfWidth[1]),
          std::min(extent, t.position[0] + t.halfWidth[0]), std::min(extent, t.position[1] + t.halfWidth[1])};
}

void fillBox(const Box& b, Rgba c, std::vector<Vertex>& out) {
  if (b.x1 <= b.x0 || b.y1 <= b.y0) return;
  const Vertex p0 = flat(b.x0, b.y0, 0, c), p1 = flat(b.x1, b.y0, 0, c), p2 = flat(b.x1, b.y1, 0, c),
               p3 = flat(b.x0, b.y1, 0, c);
  out.insert(out.end(), {p0, p1, p2, p0, p2, p3});
}

void outlineBox(const Box& b, Rgba c, std::vector<Vertex>& out) {
  if (b.x1 <= b.x0 || b.y1 <= b.y0) return;
  const Vertex p0 = flat(b.x0, b.y0, 0, c), p1 = flat(b.x1, b.y0, 0, c), p2 = flat(b.x1, b.y1, 0, c),
               p3 = flat(b.x0, b.y1, 0, c);
  out.insert(out.end(), {p0, p1, p1, p2, p2, p3, p3, p0});
}

void circlePoint(const ZoneMarker& z, int k, double& x, double& y) {
  const double a = 2.0 * M_PI * k / kCircleSegments;
  x = z.centre[0] + z.radius * std::cos(a);
  y = z.centre[1] + z.radius * std::sin(a);
}

}  // namespace

void appendTargetFills(const RenderScene& scene, double extent, std::vector<Vertex>& out) {
  for (const TargetMarker& t : scene.targets) fillBox(targetBox(t, extent), t.inside ? kTargetFillInside : kTargetFill, out);
}

void appendTargetOutlines(const RenderScene& scene, double extent, std::vector<Vertex>& out) {
  for (const TargetMarker& t : scene.targets) {
    outlineBox(targetBox(t, extent), kTargetLine, out);
    // A cross at the target itself, a quarter of the smaller band wide.
    const double arm = 0.25 * std::min(std::min(t.halfWidth[0], t.halfWidth[1]), extent);
    const double x = t.position[0], y = t.position[1];
    out.insert(out.end(), {flat(x - arm, y, 0, kTargetLine), flat(x + arm, y, 0, kTargetLine),
                           flat(x, y - arm, 0, kTargetLine), flat(x, y + arm, 0, kTargetLine)});
  }
}

void appendTargetPointers(const RenderScene& scene, std::vector<Vertex>& out) {
  constexpr double kFree = 1.0;  // [m]: a band this wide is a free component (RenderSceneBuilder's 1e3)
  const double fromX = scene.centre[0], fromY = scene.centre[1];
  for (const TargetMarker& t : scene.targets) {
    if (t.inside) continue;
    const double toX = t.halfWidth[0] < kFree ? t.position[0] : fromX;
    const double toY = t.halfWidth[1] < kFree ? t.position[1] : fromY;
    const double dx = toX - fromX, dy = toY - fromY, length = std::hypot(dx, dy);
    if (!(length > 1e-3) || !std::isfinite(length)) continue;  // within a millimetre: the band says the rest
    const double ux = dx / length, uy = dy / length;
    const double head = std::min(0.3 * length, 0.006);  // [m]
    const double c = std::cos(0.45), s = std::sin(0.45);  // the head's half angle, about 26 degrees
    out.insert(out.end(), {flat(fromX, fromY, 0, kTargetLine), flat(toX, toY, 0, kTargetLine),
                           flat(toX, toY, 0, kTargetLine),
                           flat(toX - head * (c * ux - s * uy), toY - head * (s * ux + c * uy), 0, kTargetLine),
                           flat(toX, toY, 0, kTargetLine),
                           flat(toX - head * (c * ux + s * uy), toY - head * (-s * ux + c * uy), 0, kTargetLine)});
  }
}

void appendZoneFills(const RenderScene& scene, std::vector<Vertex>& out) {
  for (const ZoneMarker& z : scene.forbidden) {
    if (!z.circle) {
      fillBox({z.min[0], z.min[1], z.max[0], z.max[1]}, kZoneFill, out);
      continue;
    }
    for (int k = 0; k < kCircleSegments; ++k) {
      double x0, y0, x1, y1;
      circlePoint(z, k, x0, y0);
      circlePoint(z, k + 1, x1, y1);
      out.insert(out.end(), {flat(z.centre[0], z.centre[1], 0, kZoneFill), flat(x0, y0, 0, kZoneFill),
                             flat(x1, y1, 0, kZoneFill)});
    }
  }
}

void appendZoneOutlines(const RenderScene& scene, std::vector<Vertex>& out) {
  for (const ZoneMarker& z : scene.forbidden) {
    if (!z.circle) {
      outlineBox({z.min[0], z.min[1], z.max[0], z.max[1]}, kZoneLine, out);
      continue;
    }
    for (int k = 0; k < kCircleSegments; ++k) {
      double x0, y0, x1, y1;
      circlePoint(z, k, x0, y0);
      circlePoint(z, k + 1, x1, y1);
      out.insert(out.end(), {flat(x0, y0, 0, kZoneLine), flat(x1, y1, 0, kZoneLine)});
    }
  }
}

void appendTraceLines(const ContactTrace& trace, double now, std::vector<Vertex>& out) {
  for (std::size_t i = 1; i < trace.size(); ++i) {
    const TracePoint& a = trace.at(i - 1);
    const TracePoint& b = trace.at(i);
    Rgba ca = kTraceColor, cb = kTraceColor;
    ca.a = float(trace.alphaForAge(now - a.time));
    cb.a = float(trace.alphaForAge(now - b.time));
    out.insert(out.end(), {flat(a.x, a.y, 0, ca), flat(b.x, b.y, 0, cb)});
  }
}

void appendExamplePath(const RenderScene& scene, std::size_t maxVertices, std::vector<Vertex>& out) {
  const auto& p = scene.examplePath;
  for (std::size_t i = 1; i < p.size() && maxVertices >= 2; i += 2, maxVertices -= 2)
    out.insert(out.end(), {flat(p[i - 1][0], p[i - 1][1], 0, kExamplePathColor), flat(p[i][0], p[i][1], 0, kExamplePathColor)});
}

void appendFlatRing(const Vec3d& centre, double inner, double outer, int segments, Rgba colour, std::vector<Vertex>& out) {
  if (!(outer > inner) || !(inner >= 0.0) || segments < 3) return;
  auto at = [&](int k, double r) {
    const double phi = 2.0 * M_PI * k / segments;
    return makeVertex(float(centre[0] + r * std::cos(phi)), float(centre[1] + r * std::sin(phi)), float(centre[2]), 0, 0, 1,
                      colour);
  };
  for (int k = 0; k < segments; ++k) {
    const Vertex a = at(k, inner), b = at(k, outer), c = at(k + 1, inner), d = at(k + 1, outer);
    out.insert(out.end(), {a, b, d, a, d, c});
  }
}

void appendSpringCoil(const Vec3d& a, const Vec3d& b, double coilRadius, int turns, std::vector<Vertex>& out) {
  const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 1e-9) || turns < 1) return;
  const double axis[3] = {d[0] / length, d[1] / length, d[2] / length};
  // Two unit vectors perpendicular to the axis: cross with the least aligned basis vector.
  const double ref[3] = {std::abs(axis[0]) < 0.9 ? 1.0 : 0.0, std::abs(axis[0]) < 0.9 ? 0.0 : 1.0, 0.0};
  double u[3] = {axis[1] * ref[2] - axis[2] * ref[1], axis[2] * ref[0] - axis[0] * ref[2],
                 axis[0] * ref[1] - axis[1] * ref[0]};
  const double un = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& x : u) x /= un;
  const double v[3] = {axis[1] * u[2] - axis[2] * u[1], axis[2] * u[0] - axis[0] * u[2],
                       axis[0] * u[1] - axis[1] * u[0]};
  constexpr int kPerTurn = 12;
  const int n = turns * kPerTurn;
  auto point = [&](int k) {
    const double s = double(k) / n, phi = 2.0 * M_PI * turns * s;
    // The coil starts and ends on the axis, so it joins both ends.
    const double r = (k == 0 || k == n) ? 0.0 : coilRadius;
    double p[3];
    for (int i = 0; i < 3; ++i) p[i] = a[i] + d[i] * s + r * (std::cos(phi) * u[i] + std::sin(phi) * v[i]);
    return makeVertex(float(p[0]), float(p[1]), float(p[2]), 0, 0, 1, kSpringColor);
  };
  Vertex prev = point(0);
  for (int k = 1; k <= n; ++k) {
    const Vertex next = point(k);
    out.insert(out.end(), {prev, next});
    prev = next;
  }
}

MeshData makeFloorGrid(double extent, double fineExtent) {
  MeshData m;
  m.primitive = Primitive::Lines;
  const Rgba fine{0.0f, 0.0f, 0.0f, 0.12f}, coarse{0.0f, 0.0f, 0.0f, 0.35f};
  const int n = int(std::floor(extent / 0.01 + 1e-9)), nFine = int(std::floor(fineExtent / 0.01 + 1e-9));
  for (int i = -n; i <= n; ++i) {
    const bool decimetre = i % 10 == 0;
    if (!decimetre && std::abs(i) > nFine) continue;
    const double c = i * 0.01, reach = decimetre ? extent : fineExtent;
    const Rgba col = decimetre ? coarse : fine;
    m.vertices.insert(m.vertices.end(), {flat(c, -reach, 0, col), flat(c, reach, 0, col),
                                         flat(-reach, c, 0, col), flat(reach, c, 0, col)});
  }
  return m;
}

}  // namespace hemiroll::render
