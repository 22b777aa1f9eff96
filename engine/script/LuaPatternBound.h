#pragma once
// An upper bound on the work of Lua's pattern matcher (lstrlib's match())
// for a pattern on a subject, so that the sandbox can refuse a pathological
// search before it runs: inside one C call no instruction hook and no clock
// can stop it (s:find(".-%b()") on 5 000 '(' runs 9 s, on 8 000 over 30 s).
//
// The bound follows the matcher item by item. W(i, m) bounds the steps of
// matching the pattern from item i on a subject with m characters left
// (a step: one character class tested, one character scanned or compared):
//   end of pattern, '(' ')' '()' '$'   1 + W(i+1, m)
//   a class c (char, '.', %a, [set])   len(c) + W(i+1, m)      len: its text, a set's members
//   c?                                 len(c) + 2 W(i+1, m)    with it, then without
//   c* c+ c-                           (m+1) len(c) + sum_{j<=m} W(i+1, j)
//                                      (max_expand's scan or min_expand's tests, then
//                                      the rest from every length the item may take)
//   %bxy, %1..%9                       (m+1) + W(i+1, m)       a scan or a comparison
//   %f[set]                            len(set) + W(i+1, m)
// W is a sum of binomials a_d C(m+d, d) (the sum over j raises each degree
// by one: the hockey-stick identity), built from the last item back in one
// pass. A search tries the match from each start: one when anchored ('^'
// with find, match, gsub), n+1 for find and match, and for gmatch and gsub,
// whose iterations together try each start at most twice, 2 (n+1).

#include <cstddef>
#include <string_view>

namespace hemiroll::script {

// How the library runs the pattern.
enum class PatternUse {
  FindOrMatch,  // string.find, string.match: one search, '^' anchors
  Gsub,         // every match, '^' anchors
  Gmatch,       // every match, '^' is a literal (Lua 5.4)
};

// Repeated items in `pattern` (for messages).
int repeatedItems(std::string_view pattern);

// The bound above on a subject of `subjectLength` characters; +inf when it
// overflows a double. A malformed pattern gets a bound of its length (Lua
// refuses it at once).
double patternStepBound(std::string_view pattern, std::size_t subjectLength, PatternUse use);

}  // namespace hemiroll::script
