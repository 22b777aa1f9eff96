#pragma once
// A heatmap over a grid of (x, y) cells with a colour bar and axis labels:
// a parameter sweep's result (leaves per cycle over k and Omega, say).
// Cells are centred on the given coordinates; their edges lie halfway to the
// neighbours (the outer ones as far out as the inner half-spacing). A cell
// without a value (NaN: the run tipped over, no rose found) is drawn light
// grey and named in the colour bar's note.

#include <optional>
#include <string>
#include <vector>

#include "game/research/report/ColourMap.h"
#include "game/research/report/PlotAxis.h"
#include "game/research/report/SvgDocument.h"

namespace hemiroll::report {

struct HeatmapDef {
  std::string title{};
  AxisSpec x{}, y{};
  std::vector<double> xCentres{}, yCentres{};  // data units, increasing
  std::vector<double> values{};              // values[iy * xCentres.size() + ix]; NaN = no value
  std::string colourBarLabel{};              // with its unit
  double valueScale = 1.0;                 // displayed value = value * valueScale (colour bar ticks, annotations)
  std::optional<double> min{}, max{};          // colour range (data units); unset: the finite values' range
  ColourMap map = ColourMap::Viridis;
  bool annotate = false;                   // write each cell's value in it (small grids)
  int decimals = 2;                        // for annotations
  std::string missingNote = "no value";    // what a grey cell means
  // Optional short text drawn in a cell whatever its value (a sweep marks
  // the cells whose runs tipped over "T"); same layout as values, "" = none.
  std::vector<std::string> marks{};
};

void drawHeatmap(SvgDocument& doc, const Rect& area, const HeatmapDef& def);
std::string renderHeatmap(const HeatmapDef& def, double width = 640.0, double height = 480.0);

}  // namespace hemiroll::report
