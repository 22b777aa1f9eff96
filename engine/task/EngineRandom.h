#pragma once
// The engine's random numbers for scripts: deterministic per seed, the same
// sequence on every platform and Lua build (math.random is removed from the
// sandbox because its generator and seeding are Lua's to change).
//
// Algorithm (documented in docs/LEVELS.md so results can be reproduced):
//   state: xoshiro256** (Blackman & Vigna, 2018), four 64-bit words, seeded
//   by running SplitMix64 from `seed` four times;
//   uniform():       (next() >> 11) * 2^-53, in [0, 1) with 53 random bits;
//   integer(lo, hi): lo + r for r uniform in [0, hi - lo], by rejection of
//                    the top partial range (no modulo bias).

#include <cstdint>

namespace hemiroll::task {

class EngineRandom {
 public:
  explicit EngineRandom(std::uint64_t seed = 0) { reseed(seed); }
  void reseed(std::uint64_t seed);

  std::uint64_t next();             // the raw xoshiro256** output
  double uniform();                 // [0, 1)
  // Uniform integer in [lo, hi]; requires lo <= hi (any span up to 2^64 - 1).
  std::int64_t integer(std::int64_t lo, std::int64_t hi);

 private:
  std::uint64_t s_[4] = {};
};

}  // namespace hemiroll::task
