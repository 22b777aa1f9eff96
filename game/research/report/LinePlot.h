#pragma once
// A line (or marker) plot with axes, ticks, grid, title, shaded intervals
// and a legend, drawn into a rectangle of an SvgDocument. Data in SI; the
// axes' scale turns them into the labels' units. A series' line breaks at
// non-finite values; points closer than a pixel to the last drawn one are
// skipped (a 35 s trace at 1 kHz stays a small file and looks the same).

#include <string>
#include <vector>

#include "game/research/report/PlotAxis.h"
#include "game/research/report/SvgDocument.h"

namespace hemiroll::report {

struct Series {
  std::string label{};             // legend text; empty: not in the legend
  std::vector<double> x{}, y{};      // data units; equal length (the shorter length is used)
  std::string colour{};            // empty: the palette's next
  double width = 1.2;            // [px] line width
  bool markers = false;          // circles at the points instead of a line
  double markerRadius = 3.0;     // [px]
};

// A shaded interval of x (a phase of a trial), labelled at its top.
struct Band {
  double from = 0.0, to = 0.0;   // data units
  std::string label{};
  std::string colour = "#999999";
  double opacity = 0.15;
};

struct LinePlotDef {
  std::string title{};
  AxisSpec x{}, y{};
  bool equalAspect = false;      // one data unit is as long on both axes (trajectories)
  std::vector<Series> series{};
  std::vector<Band> bands{};
  bool legend = true;
};

// The palette's i-th colour (cycles).
const char* paletteColour(std::size_t i);

void drawLinePlot(SvgDocument& doc, const Rect& area, const LinePlotDef& def);
// One plot as a whole SVG document.
std::string renderLinePlot(const LinePlotDef& def, double width = 640.0, double height = 480.0);

// The frame every plot shares: the data rectangle inside `area` (room for
// title, tick labels and axis labels), grid, ticks and labels.
Rect plotFrame(const Rect& area);
void drawAxes(SvgDocument& doc, const Rect& frame, const PlotAxis& x, const PlotAxis& y, const AxisSpec& xSpec,
              const AxisSpec& ySpec, const std::string& title);

}  // namespace hemiroll::report
