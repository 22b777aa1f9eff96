#pragma once
// Is a text well-formed XML, and what does it hold? For tests of the SVG
// plots (expat parses them).

#include <cstddef>
#include <string>

namespace hemiroll::test {

// "" when well-formed, else "line L, column C: what expat says".
std::string xmlProblem(const std::string& text);

// How often `what` occurs in `text` (overlapping ones counted): elements of a kind in an SVG.
std::size_t occurrences(const std::string& text, const std::string& what);

}  // namespace hemiroll::test
