#pragma once
// What stops a sweep command, as one sentence, and whose fault it is: the
// input (a spec, a part from another spec, a missing or duplicated point, a
// folder holding another sweep: exit code 2) or the environment (a file that
// cannot be written or read: exit code 1).

#include <stdexcept>
#include <string>

namespace hemiroll::game {

class SweepError : public std::runtime_error {
 public:
  enum class Kind { BadInput, Environment };
  SweepError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

}  // namespace hemiroll::game
