#include "game/research/report/LinePlot.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::report {

namespace {

constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};

// Widens the narrower axis so that a data unit has the same length in pixels on both.
void equalise(PlotAxis& x, PlotAxis& y, const Rect& frame) {
  const double perPixelX = (x.hi() - x.lo()) / frame.width, perPixelY = (y.hi() - y.lo()) / frame.height;
  if (perPixelX > perPixelY) {
    const double half = 0.5 * perPixelX * frame.height, mid = 0.5 * (y.lo() + y.hi());
    y = PlotAxis(mid - half, mid + half, y.scale());
  } else {
    const double half = 0.5 * perPixelY * frame.width, mid = 0.5 * (x.lo() + x.hi());
    x = PlotAxis(mid - half, mid + half, x.scale());
  }
}

void drawSeries(SvgDocument& doc, const Rect& f, const PlotAxis& x, const PlotAxis& y, const Series& s,
                const std::string& colour) {
  const std::size_t n = std::min(s.x.size(), s.y.size());
  std::vector<Point> run;
  auto flush = [&] {
    if (run.size() >= 2) doc.polyline(run, {.stroke = colour, .strokeWidth = s.width});
    run.clear();
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
      flush();
      continue;
    }
    const Point p{x.toPixel(s.x[i], f.x, f.right()), y.toPixel(s.y[i], f.bottom(), f.y)};
    if (s.markers) {
      doc.circle(p, s.markerRadius, {.stroke = colour, .fill = colour, .opacity = 0.85});
      continue;
    }
    const bool last = i + 1 == n;
    if (!run.empty() && !last && std::hypot(p.x - run.back().x, p.y - run.back().y) < 1.0) continue;
    run.push_back(p);
  }
  flush();
}

void drawLegend(SvgDocument& doc, const Rect& f, const LinePlotDef& def) {
  double y = f.y + 14.0;
  std::size_t index = 0;
  for (const Series& s : def.series) {
    const std::string colour = s.colour.empty() ? paletteColour(index) : s.colour;
    ++index;
    if (s.label.empty()) continue;
    if (s.markers) {
      doc.circle({f.x + 16.0, y - 4.0}, 3.0, {.stroke = colour, .fill = colour});
    } else {
      doc.line({f.x + 8.0, y - 4.0}, {f.x + 24.0, y - 4.0}, {.stroke = colour, .strokeWidth = 2.0});
    }
    doc.text({f.x + 30.0, y}, s.label, {.size = 11.0});
    y += 15.0;
  }
}

}  // namespace

const char* paletteColour(std::size_t i) { return kPalette[i % (sizeof kPalette / sizeof kPalette[0])]; }

Rect plotFrame(const Rect& a) { return {a.x + 62.0, a.y + 30.0, std::max(10.0, a.width - 78.0), std::max(10.0, a.height - 76.0)}; }

void drawAxes(SvgDocument& doc, const Rect& f, const PlotAxis& x, const PlotAxis& y, const AxisSpec& xSpec,
              const AxisSpec& ySpec, const std::string& title) {
  const Style grid{.stroke = "#e4e4e4", .strokeWidth = 1.0};
  const Style tick{.stroke = "#444444", .strokeWidth = 1.0};
  for (double v : x.ticks()) {
    const double px = x.toPixel(v, f.x, f.right());
    doc.line({px, f.y}, {px, f.bottom()}, grid);
    doc.line({px, f.bottom()}, {px, f.bottom() + 4.0}, tick);
    doc.text({px, f.bottom() + 17.0}, x.label(v), {.size = 11.0, .anchor = Anchor::Middle});
  }
  for (double v : y.ticks()) {
    const double py = y.toPixel(v, f.bottom(), f.y);
    doc.line({f.x, py}, {f.right(), py}, grid);
    doc.line({f.x - 4.0, py}, {f.x, py}, tick);
    doc.text({f.x - 7.0, py + 4.0}, y.label(v), {.size = 11.0, .anchor = Anchor::End});
  }
  doc.rect(f, {.stroke = "#444444", .strokeWidth = 1.0});
  doc.text({f.x + 0.5 * f.width, f.bottom() + 36.0}, xSpec.label, {.size = 12.0, .anchor = Anchor::Middle});
  doc.text({f.x - 48.0, f.y + 0.5 * f.height}, ySpec.label, {.size = 12.0, .anchor = Anchor::Middle, .rotate = -90.0});
  doc.text({f.x + 0.5 * f.width, f.y - 10.0}, title, {.size = 14.0, .anchor = Anchor::Middle, .bold = true});
}

void drawLinePlot(SvgDocument& doc, const Rect& area, const LinePlotDef& def) {
  DataRange xr, yr;
  for (const Series& s : def.series) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) xr.add(s.x[i]), yr.add(s.y[i]);
    }
  }
  const Rect f = plotFrame(area);
  PlotAxis x = axisFor(def.x, xr), y = axisFor(def.y, yr);
  if (def.equalAspect) equalise(x, y, f);
  drawAxes(doc, f, x, y, def.x, def.y, def.title);
  doc.beginClip(f);
  for (const Band& b : def.bands) {
    const double p0 = x.toPixel(b.from, f.x, f.right()), p1 = x.toPixel(b.to, f.x, f.right());
    doc.rect({std::min(p0, p1), f.y, std::abs(p1 - p0), f.height}, {.fill = b.colour, .opacity = b.opacity});
    if (!b.label.empty())
      doc.text({0.5 * (p0 + p1), f.bottom() - 6.0}, b.label, {.size = 10.0, .anchor = Anchor::Middle, .fill = "#555555"});
  }
  std::size_t index = 0;
  for (const Series& s : def.series) {
    drawSeries(doc, f, x, y, s, s.colour.empty() ? paletteColour(index) : s.colour);
    ++index;
  }
  doc.endClip();
  if (def.legend) drawLegend(doc, f, def);
}

std::string renderLinePlot(const LinePlotDef& def, double width, double height) {
  SvgDocument doc(width, height);
  drawLinePlot(doc, {0.0, 0.0, width, height}, def);
  return doc.str();
}

}  // namespace hemiroll::report
