#include "engine/analysis/Wording.h"

#include <cmath>
#include <cstdio>

namespace hemiroll::analysis {

std::string shortNumber(double value) {
  if (std::isnan(value)) return "not a number";
  if (std::isinf(value)) return value > 0 ? "infinite" : "minus infinite";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

}  // namespace hemiroll::analysis
