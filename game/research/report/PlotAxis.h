#pragma once
// One axis of a plot: the data range (SI), how it is shown (scale to the
// label's unit: 100 shows metres as centimetres), nice tick values (1, 2, 5
// times a power of ten) and the mapping to pixels.

#include <optional>
#include <string>
#include <vector>

namespace hemiroll::report {

struct AxisSpec {
  std::string label{};                  // with its unit, e.g. "u_a [cm]"
  double scale = 1.0;                 // displayed value = data value * scale
  std::optional<double> min{}, max{};     // in data units; unset: from the data (with a margin)
};

class PlotAxis {
 public:
  // The range [lo, hi] in data units; an empty or degenerate range is widened.
  PlotAxis(double lo, double hi, double scale);

  double lo() const { return lo_; }
  double hi() const { return hi_; }
  double scale() const { return scale_; }
  // Tick positions in data units, at nice displayed values, about `count` of them.
  std::vector<double> ticks(int count = 6) const;
  // A tick's label: the displayed value with as many decimals as the step needs.
  std::string label(double dataValue, int count = 6) const;
  // Data value -> pixel between p0 (at lo) and p1 (at hi).
  double toPixel(double value, double p0, double p1) const;

 private:
  double step(int count) const;  // displayed units

  double lo_, hi_, scale_;
};

// The range of the finite values in the lists (lo > hi when there are none).
struct DataRange {
  double lo = 1.0, hi = 0.0;
  bool empty() const { return lo > hi; }
  void add(double v);
};

// Widens [lo, hi] by `margin` of its width on both sides, applies the
// spec's fixed ends, and makes an empty range [-1, 1] and a single value v
// [v - 1, v + 1] (in displayed units).
PlotAxis axisFor(const AxisSpec& spec, DataRange range, double margin = 0.05);

}  // namespace hemiroll::report
