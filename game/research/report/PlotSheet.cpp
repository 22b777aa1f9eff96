#include "game/research/report/PlotSheet.h"

#include <algorithm>

namespace hemiroll::report {

PlotSheet::PlotSheet(int columns, double panelWidth, double panelHeight, std::string title)
    : columns_(std::max(columns, 1)), panelWidth_(panelWidth), panelHeight_(panelHeight), title_(std::move(title)) {}

std::string PlotSheet::svg() const {
  const double top = title_.empty() ? 0.0 : 36.0;
  const auto count = static_cast<int>(panels_.size());
  const int rows = std::max(1, (count + columns_ - 1) / columns_);
  SvgDocument doc(columns_ * panelWidth_, top + rows * panelHeight_);
  if (!title_.empty())
    doc.text({0.5 * doc.width(), 24.0}, title_, {.size = 16.0, .anchor = Anchor::Middle, .bold = true});
  for (int i = 0; i < count; ++i) {
    const Rect area{(i % columns_) * panelWidth_, top + (i / columns_) * panelHeight_, panelWidth_, panelHeight_};
    if (const auto* plot = std::get_if<LinePlotDef>(&panels_[static_cast<std::size_t>(i)])) {
      drawLinePlot(doc, area, *plot);
    } else {
      drawHeatmap(doc, area, std::get<HeatmapDef>(panels_[static_cast<std::size_t>(i)]));
    }
  }
  return doc.str();
}

}  // namespace hemiroll::report
