#pragma once
// An upper bound on how many steps Lua's pattern matcher may take for a
// pattern on a subject, so that the sandbox can refuse a pathological one
// (s:find(".-.-.-.-.-b") on 100k characters runs for minutes inside C, where
// no instruction hook can stop it) before it runs.
//
// The matcher backtracks over the lengths each repeated item ('*', '+', '-',
// '?') takes: with q of them on n characters there are at most C(n + q, q)
// ways to share the subject, tried from every start (one when the pattern
// is anchored with '^'). Patterns without repeats are linear and bounded by
// n per start. Escapes ('%a', '%b()', '%f[set]') and sets ('[...]') count as
// one item each.

#include <cstddef>
#include <string_view>

namespace hemiroll::script {

// Repeated items in `pattern`.
int repeatedItems(std::string_view pattern);

// starts x C(n + q, q), as a double (it overflows any integer).
double patternStepBound(std::string_view pattern, std::size_t subjectLength, bool anchoredSearch);

}  // namespace hemiroll::script
