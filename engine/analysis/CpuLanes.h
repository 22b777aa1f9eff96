#pragma once
// The widest vector of doubles this CPU runs, for the analysis' few loops
// kept in one copy per instruction set (Filters' window sums, Statistics'
// bracket, LoopCrossings' cheap angles): asked once, so that each picks its
// copy the same way. Every x86-64 has SSE2's 2 lanes.

#include <cstring>

namespace hemiroll::analysis {

// 8 (AVX-512F), 4 (AVX2) or 2.
inline int widestDoubleLanes() {
  static const int lanes = __builtin_cpu_supports("avx512f") ? 8 : __builtin_cpu_supports("avx2") ? 4 : 2;
  return lanes;
}

// The copy of a function built for widestDoubleLanes().
template <class F>
F copyForThisCpu(F lanes8, F lanes4, F lanes2) {
  const int lanes = widestDoubleLanes();
  return lanes == 8 ? lanes8 : lanes == 4 ? lanes4 : lanes2;
}

// Two doubles in one of SSE2's registers, for loops bound by divisions or
// square roots, which go hardly faster per value in wider ones: each lane
// does one value's scalar operations (no contraction: -ffp-contract=off),
// so the same bits.
typedef double DoublePair __attribute__((vector_size(2 * sizeof(double))));
inline DoublePair loadPair(const double* p) {
  DoublePair v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void storePair(double* p, DoublePair v) { std::memcpy(p, &v, sizeof v); }

}  // namespace hemiroll::analysis
