#include "game/research/report/PlotAxis.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace hemiroll::report {

void DataRange::add(double v) {
  if (!std::isfinite(v)) return;
  if (empty()) {
    lo = hi = v;
  } else {
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
}

PlotAxis::PlotAxis(double lo, double hi, double scale)
    : lo_(lo), hi_(hi), scale_(std::isfinite(scale) && scale != 0.0 ? scale : 1.0) {
  if (!std::isfinite(lo_) || !std::isfinite(hi_)) lo_ = -1.0, hi_ = 1.0;
  if (lo_ > hi_) std::swap(lo_, hi_);
  if (hi_ - lo_ <= 1e-12 * std::max(1.0, std::abs(lo_))) lo_ -= 1.0 / std::abs(scale_), hi_ += 1.0 / std::abs(scale_);
}

double PlotAxis::step(int count) const {
  const double span = std::abs(hi_ - lo_) * std::abs(scale_);
  const double raw = span / std::max(count, 2);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

std::vector<double> PlotAxis::ticks(int count) const {
  const double s = step(count);
  double a = lo_ * scale_, b = hi_ * scale_;
  if (a > b) std::swap(a, b);
  std::vector<double> out;
  for (double k = std::ceil(a / s - 1e-9); k * s <= b + 1e-9 * s && out.size() < 50; k += 1.0) out.push_back(k * s / scale_);
  return out;
}

std::string PlotAxis::label(double dataValue, int count) const {
  const double s = step(count);
  const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(s) + 1e-9)), 0, 9);
  double shown = dataValue * scale_;
  if (std::abs(shown) < 1e-9 * s) shown = 0.0;
  char buffer[48];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, shown, std::chars_format::fixed, decimals);
  return std::string(buffer, r.ptr);
}

double PlotAxis::toPixel(double value, double p0, double p1) const {
  return p0 + (value - lo_) / (hi_ - lo_) * (p1 - p0);
}

PlotAxis axisFor(const AxisSpec& spec, DataRange range, double margin) {
  const double scale = std::isfinite(spec.scale) && spec.scale != 0.0 ? std::abs(spec.scale) : 1.0;
  if (range.empty()) range = {-1.0 / scale, 1.0 / scale};
  const double pad = margin * (range.hi - range.lo);
  const double lo = spec.min.value_or(range.lo - pad), hi = spec.max.value_or(range.hi + pad);
  return PlotAxis(lo, hi, spec.scale);
}

}  // namespace hemiroll::report
