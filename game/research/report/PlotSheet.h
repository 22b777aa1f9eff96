#pragma once
// Several plots on one page: panels in a grid of `columns`, filled row by
// row, under an optional title (one trial's overview sheet).

#include <string>
#include <variant>
#include <vector>

#include "game/research/report/Heatmap.h"
#include "game/research/report/LinePlot.h"

namespace hemiroll::report {

class PlotSheet {
 public:
  PlotSheet(int columns, double panelWidth, double panelHeight, std::string title = {});

  void add(LinePlotDef plot) { panels_.emplace_back(std::move(plot)); }
  void add(HeatmapDef map) { panels_.emplace_back(std::move(map)); }
  std::size_t size() const { return panels_.size(); }

  std::string svg() const;

 private:
  int columns_;
  double panelWidth_, panelHeight_;
  std::string title_;
  std::vector<std::variant<LinePlotDef, HeatmapDef>> panels_;
};

}  // namespace hemiroll::report
