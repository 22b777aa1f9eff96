#pragma once
// The widest vector of doubles this CPU runs, for the analysis' few loops
// kept in one copy per instruction set (Filters' window sums, Statistics'
// bracket, LoopCrossings' cheap angles): asked once, so that each picks its
// copy the same way. Every x86-64 has SSE2's 2 lanes.

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

}  // namespace hemiroll::analysis
