#include "engine/human/Practice.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::human {

double practisedNoise(const PracticeDef& def, double floor, int trialsBefore) {
  if (def.noviceNoise <= floor) return floor;
  const double n = static_cast<double>(std::max(trialsBefore, 0)) + 1.0;
  return floor + (def.noviceNoise - floor) * std::pow(n, -def.exponent);
}

}  // namespace hemiroll::human
