#include "engine/task/EngineRandom.h"

namespace hemiroll::task {

namespace {

std::uint64_t splitMix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

void EngineRandom::reseed(std::uint64_t seed) {
  // SplitMix64 never yields four zero words in a row, so the xoshiro state
  // is never the all-zero fixed point.
  for (std::uint64_t& word : s_) word = splitMix64(seed);
}

std::uint64_t EngineRandom::next() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double EngineRandom::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

std::int64_t EngineRandom::integer(std::int64_t lo, std::int64_t hi) {
  // Work in unsigned arithmetic: hi - lo may exceed INT64_MAX.
  const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
  std::uint64_t r;
  if (span == ~std::uint64_t{0}) {
    r = next();
  } else {
    const std::uint64_t range = span + 1;
    // Accept only draws below the largest multiple of `range`: every residue
    // is then equally likely.
    const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % range + 1) % range;
    do r = next();
    while (r > limit);
    r %= range;
  }
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + r);
}

}  // namespace hemiroll::task
