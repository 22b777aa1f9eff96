#pragma once
// game/research/report: plots as SVG files, for `hemiroll analyze`, `hemiroll
// figures` and the parameter sweep. Standard library only; text out.
//
// Owns: the SVG document (escaping, number formatting, never a NaN
// coordinate: a line breaks where its data are not finite), axes with nice
// ticks and unit scaling (data in SI, labels in any unit: scale 100 shows
// metres as centimetres), line/marker plots with shaded intervals and a
// legend, heatmaps with a colour bar, colour maps, and sheets of panels.
// Must not know: the analysis, recordings, the physics, files (callers
// write the text where they like, e.g. record::writeFileAtomically).
//
// Usage:
//   report::LinePlotDef plot{.title = "contact point", .x = {"u_a [cm]", 100.0}, .y = {"v_a [cm]", 100.0},
//                            .equalAspect = true};
//   plot.series.push_back({.label = "trace", .x = u, .y = v});
//   std::string svg = report::renderLinePlot(plot);            // one plot, 640 x 480
//   report::HeatmapDef map{.title = "leaves", .x = {"k"}, .y = {"Omega [rad/s]"},
//                          .xCentres = ks, .yCentres = omegas, .values = leaves,   // values[iy * nx + ix]
//                          .colourBarLabel = "leaves per cycle"};
//   report::PlotSheet sheet(2, 520, 400, "trial 3");          // two columns of panels
//   sheet.add(plot); sheet.add(map);
//   std::string page = sheet.svg();

#include "game/research/report/ColourMap.h"
#include "game/research/report/Heatmap.h"
#include "game/research/report/LinePlot.h"
#include "game/research/report/PlotAxis.h"
#include "game/research/report/PlotSheet.h"
#include "game/research/report/SvgDocument.h"
