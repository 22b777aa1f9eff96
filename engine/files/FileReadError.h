#pragma once
// The one exception engine/files throws: a sentence that names the file and
// what is wrong with it ("results.csv: not a regular file (a FIFO)").

#include <stdexcept>
#include <string>

namespace hemiroll::files {

class FileReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hemiroll::files
