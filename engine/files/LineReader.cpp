#include "engine/files/LineReader.h"

#include <cstring>

#include "engine/files/FileReadError.h"
#include "engine/files/PrintableName.h"

namespace hemiroll::files {

LineReader::LineReader(CheckedFile& file, std::size_t maxLineBytes)
    : file_(file), maxLine_(maxLineBytes), buffer_(std::max<std::size_t>(maxLineBytes + 2, 64 * 1024), '\0') {}

bool LineReader::fill() {
  if (eof_) return false;
  if (begin_ > 0) {  // keep the partial line at the front
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buffer_.size()) return false;
  const std::size_t n = file_.read(buffer_.data() + end_, buffer_.size() - end_);
  if (n == 0) eof_ = true;
  end_ += n;
  return n > 0;
}

bool LineReader::next(std::string_view& line, bool& complete) {
  std::size_t scanned = begin_;
  for (;;) {
    const void* found = std::memchr(buffer_.data() + scanned, '\n', end_ - scanned);
    if (found != nullptr) {
      const std::size_t newline = static_cast<std::size_t>(static_cast<const char*>(found) - buffer_.data());
      std::size_t length = newline - begin_;
      if (length > maxLine_ + 1) break;  // + 1: a '\r' before the '\n'
      line = std::string_view(buffer_.data() + begin_, length);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (line.size() > maxLine_) break;
      complete = true;
      ++lineNumber_;
      offset_ += length + 1;
      begin_ = newline + 1;
      return true;
    }
    scanned = end_;
    if (end_ - begin_ > maxLine_ + 1) break;
    const std::size_t before = begin_;
    if (!fill()) {
      if (end_ == begin_) return false;
      // The last line has no '\n': a cut-off write.
      if (end_ - begin_ > maxLine_) break;
      line = std::string_view(buffer_.data() + begin_, end_ - begin_);
      complete = false;
      ++lineNumber_;
      offset_ += end_ - begin_;
      begin_ = end_;
      return true;
    }
    scanned -= before - begin_;  // fill() moved the unread bytes to the front
  }
  throw FileReadError(printablePath(file_.path()) + ": line " + std::to_string(lineNumber_ + 1) + ": longer than the " +
                      describeSize(maxLine_) + " a line of a " + file_.kind().name + " may be");
}

}  // namespace hemiroll::files
