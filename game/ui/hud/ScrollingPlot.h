#pragma once
// A bounded ring of samples for the HUD's real-time plots (the paper's
// Fig. 5 style trace of one state channel against time). Storage is fixed at
// construction: push() and the plot drawing allocate nothing.

#include <cstddef>
#include <vector>

namespace hemiroll::game {

class ScrollingPlot {
 public:
  explicit ScrollingPlot(std::size_t capacity = 600);  // 600 frames: ~10 s at 60 fps

  void push(float value);
  void clear() { count_ = 0; head_ = 0; }
  std::size_t size() const { return count_; }
  std::size_t capacity() const { return values_.size(); }
  // The i-th oldest sample, 0 <= i < size().
  float at(std::size_t i) const;
  float min() const;
  float max() const;

  // ImGui::PlotLines' values_getter over this ring.
  static float getter(void* data, int index);

 private:
  std::vector<float> values_;
  std::size_t head_ = 0;   // where the next sample goes
  std::size_t count_ = 0;
};

}  // namespace hemiroll::game
