#pragma once
// A definition's field that is wrong and what is wrong with it, as two
// values. Validators return it instead of one sentence so that a data-file
// loader (engine/script) can point at the field's line without taking the
// sentence apart again.

#include <string>

namespace hemiroll::physics {

struct FieldError {
  std::string field;    // as a data file writes it: "params.R", "kr"
  std::string message;  // the rest of the sentence: "(radius) must be a positive ..."

  // "params.R (radius) must be ...": for callers that show one line.
  std::string sentence() const { return field + " " + message; }
};

}  // namespace hemiroll::physics
