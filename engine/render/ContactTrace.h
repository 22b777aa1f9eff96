#pragma once
// The contact point's path on the plane: a fixed-capacity ring of points,
// oldest overwritten first, so memory is bounded however long a trial runs.
// Points closer than `minSpacing` to the last one are not stored (a resting
// hemisphere does not fill the ring). No allocation after construction.

#include <cstddef>
#include <vector>

namespace hemiroll::render {

struct ContactTraceDef {
  std::size_t capacity = 4096;  // points kept; > 1
  double minSpacing = 5e-4;     // [m]: 0.5 mm, well below a pixel at the follow camera's zoom
  double fadeTime = 20.0;       // [s]: a point this old is drawn at the minimum alpha
};

struct TracePoint {
  double x = 0.0, y = 0.0;  // (u_a, v_a) [m]
  double time = 0.0;        // [s]
};

class ContactTrace {
 public:
  explicit ContactTrace(ContactTraceDef def = {});

  // Non-finite points are ignored (a broken state must not reach the GPU).
  void push(double x, double y, double time);
  void clear();

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return points_.size(); }
  // i = 0 is the oldest point kept.
  const TracePoint& at(std::size_t i) const { return points_[(head_ + i) % points_.size()]; }
  const ContactTraceDef& def() const { return def_; }
  // Opacity of a point of this age in [minAlpha, 1], linear over fadeTime.
  double alphaForAge(double age) const;
  static constexpr double kMinAlpha = 0.15;

 private:
  ContactTraceDef def_;
  std::vector<TracePoint> points_;
  std::size_t head_ = 0;  // index of the oldest point
  std::size_t size_ = 0;
};

}  // namespace hemiroll::render
