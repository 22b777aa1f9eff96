#pragma once
// One checked way to read a file the program did not just write itself:
//   - it is opened without blocking (O_NONBLOCK), so a FIFO in its place
//     cannot hang the open, and then checked with fstat on the open
//     descriptor (no window for a swap between the check and the read):
//     anything but a regular file (FIFO, device such as /dev/zero,
//     directory, socket) is refused;
//   - its size is checked against its kind's cap (FileKinds.h) before a
//     byte is read, and reading stops one byte past the cap whatever the
//     file grew to since.
// Large kinds are read as a stream (read(), LineReader); small ones whole
// (readAll, readCheckedFile). Failures throw FileReadError naming the file.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "engine/files/FileKinds.h"

namespace hemiroll::files {

class CheckedFile {
 public:
  CheckedFile(const std::filesystem::path& path, const FileKind& kind);
  ~CheckedFile();
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;

  // The size fstat gave when the file was opened [bytes].
  std::uintmax_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }
  const FileKind& kind() const { return kind_; }

  // Up to `capacity` bytes into `buffer`; 0 at the end of the file. Throws
  // when a read fails or the file has grown past its kind's cap.
  std::size_t read(char* buffer, std::size_t capacity);
  // The rest of the file.
  std::string readAll();

 private:
  std::filesystem::path path_;
  FileKind kind_;
  int fd_ = -1;
  std::uintmax_t size_ = 0;
  std::uintmax_t consumed_ = 0;
};

// The whole file, checked as above.
std::string readCheckedFile(const std::filesystem::path& path, const FileKind& kind);

// For C code that must not unwind (a Lua C function): the same checks with
// the outcome returned. checkedSize opens, checks and gives the size;
// readCheckedInto reads the whole file into `buffer` (ok only when it all
// fits in `capacity` bytes). error holds the sentence when !ok.
struct CheckedRead {
  bool ok = false;
  std::uintmax_t size = 0;
  char error[512] = {};
};
CheckedRead checkedSize(const char* path, const FileKind& kind) noexcept;
CheckedRead readCheckedInto(const char* path, const FileKind& kind, char* buffer, std::size_t capacity) noexcept;

// "4 MiB", "3.2 GiB", "1234 bytes": sizes in messages.
std::string describeSize(std::uintmax_t bytes);

}  // namespace hemiroll::files
