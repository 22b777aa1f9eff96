#pragma once
// What can stop a research session before or between trials, as one
// sentence, and whose fault it is: the input (a protocol, level or bot that
// cannot be used, a protocol changed since the session started, a bad id:
// exit code 2) or the environment (a folder that cannot be written or was
// changed by hand: exit code 1).

#include <stdexcept>
#include <string>

namespace hemiroll::game {

class SessionError : public std::runtime_error {
 public:
  enum class Kind { BadInput, Environment };
  SessionError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

}  // namespace hemiroll::game
