#include "game/ui/hud/ScrollingPlot.h"

#include <algorithm>
#include <limits>

namespace hemiroll::game {

ScrollingPlot::ScrollingPlot(std::size_t capacity) : values_(std::max<std::size_t>(capacity, 1), 0.0f) {}

void ScrollingPlot::push(float value) {
  values_[head_] = value;
  head_ = (head_ + 1) % values_.size();
  count_ = std::min(count_ + 1, values_.size());
}

float ScrollingPlot::at(std::size_t i) const {
  const std::size_t oldest = (head_ + values_.size() - count_) % values_.size();
  return values_[(oldest + i) % values_.size()];
}

float ScrollingPlot::min() const {
  float m = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < count_; ++i) m = std::min(m, at(i));
  return count_ ? m : 0.0f;
}

float ScrollingPlot::max() const {
  float m = -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < count_; ++i) m = std::max(m, at(i));
  return count_ ? m : 0.0f;
}

float ScrollingPlot::getter(void* data, int index) {
  return static_cast<const ScrollingPlot*>(data)->at(static_cast<std::size_t>(index));
}

}  // namespace hemiroll::game
