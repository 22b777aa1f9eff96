#pragma once
// The one exception engine/script throws. Its message is complete and meant
// for a person: it names the file and either the line ("rose.lua:12: ...") or
// the field path ("rose.lua: drive.r1: ..."). Callers print it as it is.
//
// FieldFailure is the ScriptError of a wrong field in a data table: the same
// sentence, and its parts as values, so that DataFileLoader can add the
// field's line without taking the sentence apart.

#include <stdexcept>
#include <string>
#include <utility>

#include "engine/physics/FieldError.h"

namespace hemiroll::script {

using physics::FieldError;

class ScriptError : public std::runtime_error {
 public:
  explicit ScriptError(const std::string& message) : std::runtime_error(message) {}
};

class FieldFailure : public ScriptError {
 public:
  // "source: field: message", or "source: message" for field "" (the table itself).
  FieldFailure(std::string source, FieldError error)
      : ScriptError(source + ": " + (error.field.empty() ? "" : error.field + ": ") + error.message),
        source_(std::move(source)),
        error_(std::move(error)) {}

  const std::string& source() const { return source_; }
  const FieldError& error() const { return error_; }

 private:
  std::string source_;
  FieldError error_;
};

}  // namespace hemiroll::script
