#pragma once
// How the detectors word a number in their "not found: why" sentences:
// three significant digits, no locale, finite (a non-finite value is said
// in words, so no reason ever carries "nan").

#include <string>

namespace hemiroll::analysis {

std::string shortNumber(double value);

}  // namespace hemiroll::analysis
