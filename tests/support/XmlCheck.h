#pragma once
// Is a text well-formed XML? For tests of the SVG plots (expat parses it).

#include <string>

namespace hemiroll::test {

// "" when well-formed, else "line L, column C: what expat says".
std::string xmlProblem(const std::string& text);

}  // namespace hemiroll::test
