#pragma once
// `hemiroll version`: the program's version, one line on stdout.

#include <string>
#include <vector>

namespace hemiroll::game {

int runVersionCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
