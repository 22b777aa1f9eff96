#pragma once
// Small statistics on plain vectors: what every detector reports its
// measurements with. Inputs are finite (the detectors drop non-finite
// samples before they get here); empty input gives 0, never NaN.

#include <span>
#include <vector>

namespace hemiroll::analysis {

// A measured quantity: a central value and how much it varies over the
// items it was measured on (leaves, cycles, loops). SI units as named by the
// field that holds it.
struct Estimate {
  double value = 0.0;
  double spread = 0.0;  // sample standard deviation over the items; 0 for one item
  int count = 0;        // items measured
};

double mean(std::span<const double> values);
double median(std::span<const double> values);
// q in [0, 1], linear interpolation between order statistics.
double quantile(std::span<const double> values, double q);
// quantile at each of qs, to the bit (issue 32: the rose took its median
// and two percentiles of the same distances by three copies and three
// selections over all of them). Long columns: each q within its own bracket
// (Statistics.cpp); others: one copy, each selection within the part the
// one above it left.
std::vector<double> quantiles(std::span<const double> values, std::span<const double> qs);
double standardDeviation(std::span<const double> values);  // sample (n - 1); 0 below two values
// Median as the value (robust to a stray leaf or loop), standard deviation as the spread.
Estimate summarize(std::span<const double> values);

}  // namespace hemiroll::analysis
