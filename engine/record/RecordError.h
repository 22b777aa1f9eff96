#pragma once
// The one exception engine/record throws: a sentence naming the file (and
// the line or byte where that helps) and what is wrong with it.

#include <stdexcept>
#include <string>

namespace hemiroll::record {

class RecordError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hemiroll::record
