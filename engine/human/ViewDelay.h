#pragma once
// The visual delay: what the screen showed `delay` ago. A ring of one view
// per tick, sized once (no allocation per tick); before the first `delay`
// has passed there is nothing to see yet.

#include <cstddef>
#include <vector>

#include "engine/human/ScreenView.h"

namespace hemiroll::human {

class ViewDelay {
 public:
  // `delay` and `tick` [s], both > 0.
  ViewDelay(double delay, double tick);

  // The view of this tick; returns the one shown `delay` ago, or null while
  // the first views are still on their way.
  const ScreenView* push(const ScreenView& now);
  // How many ticks late a view arrives.
  std::size_t lagTicks() const { return lag_; }

 private:
  std::size_t lag_;
  std::vector<ScreenView> ring_;
  std::size_t pushed_ = 0;
};

}  // namespace hemiroll::human
