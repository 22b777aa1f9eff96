#include "game/research/report/Heatmap.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "game/research/report/LinePlot.h"

namespace hemiroll::report {

namespace {

// Cell edges around increasing centres.
std::vector<double> edgesOf(const std::vector<double>& c) {
  std::vector<double> e(c.size() + 1);
  if (c.size() == 1) return {c[0] - 0.5, c[0] + 0.5};
  for (std::size_t i = 1; i < c.size(); ++i) e[i] = 0.5 * (c[i - 1] + c[i]);
  e.front() = c.front() - (e[1] - c.front());
  e.back() = c.back() + (c.back() - e[c.size() - 1]);
  return e;
}

bool usable(const std::vector<double>& c) {
  if (c.empty()) return false;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (!std::isfinite(c[i]) || (i > 0 && c[i] <= c[i - 1])) return false;
  return true;
}

std::string fixed(double v, int decimals) {
  char buffer[48];
  if (std::abs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, std::clamp(decimals, 0, 9));
  return std::string(buffer, r.ptr);
}

void drawColourBar(SvgDocument& doc, const Rect& bar, const HeatmapDef& def, double lo, double hi, bool anyMissing) {
  constexpr int kSteps = 64;
  for (int i = 0; i < kSteps; ++i) {
    const double h = bar.height / kSteps;
    doc.rect({bar.x, bar.bottom() - (i + 1) * h, bar.width, h + 0.5},
             {.fill = colourAt(def.map, (i + 0.5) / kSteps)});
  }
  doc.rect(bar, {.stroke = "#444444"});
  const PlotAxis axis(lo, hi, def.valueScale);
  for (double v : axis.ticks(5)) {
    const double py = axis.toPixel(v, bar.bottom(), bar.y);
    doc.line({bar.right(), py}, {bar.right() + 4.0, py}, {.stroke = "#444444"});
    doc.text({bar.right() + 6.0, py + 4.0}, axis.label(v, 5), {.size = 10.0});
  }
  doc.text({bar.right() + 46.0, bar.y + 0.5 * bar.height}, def.colourBarLabel,
           {.size = 12.0, .anchor = Anchor::Middle, .rotate = 90.0});
  if (anyMissing) {
    doc.rect({bar.x, bar.bottom() + 12.0, bar.width, 10.0}, {.stroke = "#444444", .fill = "#dddddd"});
    doc.text({bar.right() + 4.0, bar.bottom() + 21.0}, def.missingNote, {.size = 10.0});
  }
}

}  // namespace

void drawHeatmap(SvgDocument& doc, const Rect& area, const HeatmapDef& def) {
  // Room on the right for the colour bar, its ticks and its label (inside the area, so
  // that panels side by side on a sheet do not overlap).
  const Rect plotArea{area.x, area.y, std::max(20.0, area.width - 92.0), area.height};
  const Rect f = plotFrame(plotArea);
  const std::size_t nx = def.xCentres.size(), ny = def.yCentres.size();
  const bool ok = usable(def.xCentres) && usable(def.yCentres) && def.values.size() == nx * ny;
  if (!ok) {
    const PlotAxis x = axisFor(def.x, {}), y = axisFor(def.y, {});
    drawAxes(doc, f, x, y, def.x, def.y, def.title);
    doc.text({f.x + 0.5 * f.width, f.y + 0.5 * f.height}, "no grid to show", {.anchor = Anchor::Middle});
    return;
  }
  const std::vector<double> xe = edgesOf(def.xCentres), ye = edgesOf(def.yCentres);
  const PlotAxis x(def.x.min.value_or(xe.front()), def.x.max.value_or(xe.back()), def.x.scale);
  const PlotAxis y(def.y.min.value_or(ye.front()), def.y.max.value_or(ye.back()), def.y.scale);
  DataRange vr;
  for (double v : def.values) vr.add(v);
  double lo = def.min.value_or(vr.empty() ? 0.0 : vr.lo), hi = def.max.value_or(vr.empty() ? 1.0 : vr.hi);
  if (!(hi > lo)) lo -= 0.5, hi += 0.5;

  bool anyMissing = false;
  doc.beginClip(f);
  for (std::size_t iy = 0; iy < ny; ++iy) {
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const double v = def.values[iy * nx + ix];
      const double x0 = x.toPixel(xe[ix], f.x, f.right()), x1 = x.toPixel(xe[ix + 1], f.x, f.right());
      const double y0 = y.toPixel(ye[iy], f.bottom(), f.y), y1 = y.toPixel(ye[iy + 1], f.bottom(), f.y);
      const Rect cell{std::min(x0, x1), std::min(y0, y1), std::abs(x1 - x0) + 0.5, std::abs(y1 - y0) + 0.5};
      anyMissing = anyMissing || !std::isfinite(v);
      const std::string colour = std::isfinite(v) ? colourAt(def.map, (v - lo) / (hi - lo)) : "#dddddd";
      doc.rect(cell, {.fill = colour});
      // Text on the dark end of viridis is white.
      const bool dark = std::isfinite(v) && def.map == ColourMap::Viridis && (v - lo) / (hi - lo) < 0.6;
      const std::string* mark = def.marks.size() == def.values.size() ? &def.marks[iy * nx + ix] : nullptr;
      const std::string text = mark != nullptr && !mark->empty()          ? *mark
                               : def.annotate && std::isfinite(v) ? fixed(v * def.valueScale, def.decimals)
                                                                  : std::string();
      if (!text.empty())
        doc.text({cell.x + 0.5 * cell.width, cell.y + 0.5 * cell.height + 4.0}, text,
                 {.size = 10.0, .anchor = Anchor::Middle, .fill = dark ? "#ffffff" : "#222222"});
    }
  }
  doc.endClip();
  drawAxes(doc, f, x, y, def.x, def.y, def.title);
  drawColourBar(doc, {f.right() + 24.0, f.y, 16.0, f.height}, def, lo, hi, anyMissing);
}

std::string renderHeatmap(const HeatmapDef& def, double width, double height) {
  SvgDocument doc(width, height);
  drawHeatmap(doc, {0.0, 0.0, width, height}, def);
  return doc.str();
}

}  // namespace hemiroll::report
