#pragma once
// Which points a run computes: shard i of N takes every point whose index
// is i modulo N (neighbouring points cost about the same, so striding spreads
// the slow corners of a grid over all shards). N = 1 is the whole sweep.
// Its files in the output folder are "sweep.*" for the whole, else
// "part-<i>-of-<N>.*", so the shards of one job array may share a folder.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hemiroll::game {

struct SweepShard {
  long long index = 0;
  long long count = 1;

  bool whole() const { return count == 1; }
  // "sweep" or "part-<i>-of-<N>": the stem of the shard's files.
  std::string stem() const;
  // "i/N" for messages.
  std::string label() const;
  // How many of `total` points the shard holds, and which (increasing).
  long long size(long long total) const;
  std::vector<long long> points(long long total) const;

  // "i/N" with 0 <= i < N, N >= 1; nullopt otherwise.
  static std::optional<SweepShard> parse(std::string_view text);
};

}  // namespace hemiroll::game
