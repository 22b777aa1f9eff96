#pragma once
// The one exception engine/script throws. Its message is complete and meant
// for a person: it names the file and either the line ("rose.lua:12: ...") or
// the field path ("rose.lua: drive.r1: ..."). Callers print it as it is.

#include <stdexcept>
#include <string>

namespace hemiroll::script {

class ScriptError : public std::runtime_error {
 public:
  explicit ScriptError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace hemiroll::script
