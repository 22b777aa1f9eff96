#pragma once
// Every detector works on samples equally spaced in time: moving averages,
// periodograms and local slopes assume it. Recordings are nearly so (a
// dropped row leaves a gap), simulator output is exactly so but often ten
// times denser than needed. resampleUniform() turns any sampled channels
// into that form:
//  - rows whose time or any channel is not finite are dropped, and so are
//    rows whose time does not increase (a repeated or out-of-order row);
//  - gaps longer than `maxGap` split the data; the longest piece (in time)
//    is kept, so a long dropout never gets bridged by a straight line;
//  - the kept piece is interpolated linearly onto t0 + i dt, with dt the
//    median native spacing or 1 / maxRate, whichever is longer (a 1 kHz run
//    becomes 100 Hz; the 100 Hz recordings keep their own sample times).
// Linear interpolation of a 1 kHz simulation at 100 Hz aliases nothing that
// matters here: the model's motion has no content near 50 Hz.

#include <span>
#include <string>
#include <vector>

namespace hemiroll::analysis {

struct ResampleDef {
  double maxRate = 100.0;  // [Hz] the densest grid produced
  double maxGap = 0.25;    // [s] a longer stretch without finite rows splits the data
  int minSamples = 16;     // fewer usable samples than this is "not enough data"
  bool operator==(const ResampleDef&) const = default;
};

struct UniformSeries {
  double t0 = 0.0;  // [s] time of sample 0
  double dt = 0.0;  // [s] spacing
  std::vector<std::vector<double>> channels;  // as given, each `size()` long
  std::size_t droppedRows = 0;                // non-finite or non-increasing rows
  std::string problem;                        // non-empty: no usable series, and why

  bool ok() const { return problem.empty(); }
  std::size_t size() const { return channels.empty() ? 0 : channels.front().size(); }
  double time(std::size_t i) const { return t0 + static_cast<double>(i) * dt; }
  double duration() const { return size() < 2 ? 0.0 : dt * static_cast<double>(size() - 1); }
};

// All channels must be as long as `time` (else `problem` says so).
UniformSeries resampleUniform(std::span<const double> time, std::span<const std::span<const double>> channels,
                              const ResampleDef& def = {});

}  // namespace hemiroll::analysis
