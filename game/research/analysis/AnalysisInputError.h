#pragma once
// What `hemiroll analyze` reports for bad input: one sentence naming the
// file (and line) and what is wrong; the command exits with 2.

#include <stdexcept>

namespace hemiroll::game {

class AnalysisInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hemiroll::game
