#include "engine/script/LuaPatternBound.h"

namespace hemiroll::script {

namespace {

// The end of the single-character class that starts at `i` (one past it).
std::size_t classEnd(std::string_view p, std::size_t i) {
  if (i >= p.size()) return i;
  if (p[i] == '%') {
    if (i + 1 >= p.size()) return p.size();
    if (p[i + 1] == 'b') return std::min(p.size(), i + 4);  // %bxy
    if (p[i + 1] == 'f') {                                  // %f[set]
      std::size_t j = i + 2;
      return j < p.size() && p[j] == '[' ? classEnd(p, j) : j;
    }
    return i + 2;
  }
  if (p[i] == '[') {
    std::size_t j = i + 1;
    if (j < p.size() && p[j] == '^') ++j;
    // A ']' first in the set is a member, not its end.
    if (j < p.size() && p[j] == ']') ++j;
    while (j < p.size() && p[j] != ']') j += p[j] == '%' ? 2 : 1;
    return std::min(p.size(), j + 1);
  }
  return i + 1;
}

}  // namespace

int repeatedItems(std::string_view p) {
  int repeats = 0;
  std::size_t i = p.size() > 0 && p[0] == '^' ? 1 : 0;
  while (i < p.size()) {
    if (p[i] == '(' || p[i] == ')') {
      ++i;
      continue;
    }
    const bool special = p[i] == '%' && i + 1 < p.size() && (p[i + 1] == 'b' || p[i + 1] == 'f');
    i = classEnd(p, i);
    if (!special && i < p.size() && (p[i] == '*' || p[i] == '+' || p[i] == '-' || p[i] == '?')) {
      ++repeats;
      ++i;
    }
  }
  return repeats;
}

double patternStepBound(std::string_view pattern, std::size_t subjectLength, bool anchoredSearch) {
  const double n = static_cast<double>(subjectLength);
  const int q = repeatedItems(pattern);
  const bool anchored = anchoredSearch && !pattern.empty() && pattern[0] == '^';
  double ways = 1.0;  // C(n + q, q), built up factor by factor
  for (int k = 1; k <= q; ++k) ways *= (n + k) / k;
  const double perStart = ways + n;
  return (anchored ? 1.0 : n + 1.0) * perStart;
}

}  // namespace hemiroll::script
