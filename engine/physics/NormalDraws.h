#pragma once
// Standard normal draws from splitmix64 and Box-Muller: the same seed gives
// the same draws on any standard library (std::normal_distribution is not
// specified bit for bit), so a search or a simulated person seeded alike
// plays alike everywhere. Not physics, but below everything that draws:
// the autopilot's landing search and the human model.

#include <cstdint>

namespace hemiroll::physics {

class NormalDraws {
 public:
  explicit NormalDraws(std::uint64_t seed = 0) : state_(seed) {}
  double operator()();

 private:
  std::uint64_t next();
  std::uint64_t state_;
};

}  // namespace hemiroll::physics
