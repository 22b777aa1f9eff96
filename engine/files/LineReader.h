#pragma once
// Lines of a CheckedFile one at a time, through a fixed buffer: memory
// stays at the longest line allowed, however large the file (a recording of
// a day, a sweep of a million points). A line longer than the cap is
// refused with its number (a 3 GB file of zeros is one such line, refused
// after the cap, not after 3 GB).

#include <cstddef>
#include <string>
#include <string_view>

#include "engine/files/CheckedFile.h"

namespace hemiroll::files {

class LineReader {
 public:
  // maxLineBytes: the longest line this kind has, with room to spare.
  LineReader(CheckedFile& file, std::size_t maxLineBytes);

  // The next line, without its '\n' (and a '\r' before it), valid until
  // the next call. False at the end of the file. `complete` says whether
  // the line ended with '\n' (a cut-off last line does not). Throws
  // FileReadError "path: line N: longer than ..." for an overlong line.
  bool next(std::string_view& line, bool& complete);
  bool next(std::string_view& line) {
    bool complete = false;
    return next(line, complete);
  }
  // The number of the line next() returned last (1-based).
  std::size_t lineNumber() const { return lineNumber_; }
  // Bytes consumed up to the end of the last line returned.
  std::uintmax_t offset() const { return offset_; }

 private:
  bool fill();

  CheckedFile& file_;
  std::size_t maxLine_;
  std::string buffer_;
  std::size_t begin_ = 0, end_ = 0;  // unread bytes: buffer_[begin_, end_)
  bool eof_ = false;
  std::size_t lineNumber_ = 0;
  std::uintmax_t offset_ = 0;
};

}  // namespace hemiroll::files
