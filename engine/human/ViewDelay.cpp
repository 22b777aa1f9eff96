#include "engine/human/ViewDelay.h"

#include <cmath>

namespace hemiroll::human {

ViewDelay::ViewDelay(double delay, double tick)
    : lag_(static_cast<std::size_t>(std::llround(delay / tick))), ring_(lag_ + 1) {}

const ScreenView* ViewDelay::push(const ScreenView& now) {
  ring_[pushed_ % ring_.size()] = now;
  ++pushed_;
  if (pushed_ <= lag_) return nullptr;
  // The slot after the newest holds the view lag_ ticks older than it.
  return &ring_[pushed_ % ring_.size()];
}

}  // namespace hemiroll::human
