#include "engine/render/ContactTrace.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hemiroll::render {

ContactTrace::ContactTrace(ContactTraceDef def) : def_(def) {
  if (def_.capacity < 2) throw std::invalid_argument("ContactTraceDef.capacity must be at least 2");
  if (!(def_.minSpacing >= 0.0)) throw std::invalid_argument("ContactTraceDef.minSpacing must be >= 0");
  if (!(def_.fadeTime > 0.0)) throw std::invalid_argument("ContactTraceDef.fadeTime must be > 0");
  points_.resize(def_.capacity);
}

void ContactTrace::push(double x, double y, double time) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(time)) return;
  if (size_ > 0) {
    const TracePoint& last = at(size_ - 1);
    if (std::hypot(x - last.x, y - last.y) < def_.minSpacing) return;
  }
  const std::size_t cap = points_.size();
  if (size_ < cap) {
    points_[(head_ + size_) % cap] = {x, y, time};
    ++size_;
  } else {
    points_[head_] = {x, y, time};  // the oldest slot becomes the newest
    head_ = (head_ + 1) % cap;
  }
}

void ContactTrace::clear() {
  head_ = 0;
  size_ = 0;
}

double ContactTrace::alphaForAge(double age) const {
  const double a = 1.0 - std::max(0.0, age) / def_.fadeTime;
  return std::clamp(a, kMinAlpha, 1.0);
}

}  // namespace hemiroll::render
