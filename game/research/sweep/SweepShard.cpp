#include "game/research/sweep/SweepShard.h"

#include "game/cli/ArgumentReader.h"

namespace hemiroll::game {

std::string SweepShard::stem() const {
  return whole() ? "sweep" : "part-" + std::to_string(index) + "-of-" + std::to_string(count);
}

std::string SweepShard::label() const { return std::to_string(index) + "/" + std::to_string(count); }

long long SweepShard::size(long long total) const { return total > index ? (total - index + count - 1) / count : 0; }

std::vector<long long> SweepShard::points(long long total) const {
  std::vector<long long> out;
  out.reserve(static_cast<std::size_t>(size(total)));
  for (long long i = index; i < total; i += count) out.push_back(i);
  return out;
}

std::optional<SweepShard> SweepShard::parse(std::string_view text) {
  const std::vector<std::string> parts = cli::splitList(text, '/');
  unsigned long long i = 0, n = 0;
  // A million shards is more than any cluster's job array allows.
  if (parts.size() != 2 || !cli::readUnsigned(parts[0], i) || !cli::readUnsigned(parts[1], n) || n == 0 ||
      n > 1'000'000 || i >= n)
    return std::nullopt;
  return SweepShard{static_cast<long long>(i), static_cast<long long>(n)};
}

}  // namespace hemiroll::game
