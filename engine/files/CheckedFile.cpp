#include "engine/files/CheckedFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "engine/files/FileReadError.h"
#include "engine/files/PrintableName.h"

namespace hemiroll::files {

namespace {

const char* typeName(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a plain file";  // unreachable on Linux
}

}  // namespace

std::string describeSize(std::uintmax_t bytes) {
  char text[64];
  const auto show = [&](std::uintmax_t unit, const char* name) {
    if (bytes % unit == 0)
      std::snprintf(text, sizeof text, "%ju %s", bytes / unit, name);
    else
      std::snprintf(text, sizeof text, "%.1f %s", static_cast<double>(bytes) / static_cast<double>(unit), name);
  };
  if (bytes >= kGiB)
    show(kGiB, "GiB");
  else if (bytes >= kMiB)
    show(kMiB, "MiB");
  else if (bytes >= kKiB)
    show(kKiB, "KiB");
  else
    std::snprintf(text, sizeof text, "%ju bytes", bytes);
  return text;
}

CheckedFile::CheckedFile(const std::filesystem::path& path, const FileKind& kind) : path_(path), kind_(kind) {
  const std::string name = printablePath(path);
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd_ < 0) {
    const int error = errno;
    throw FileReadError(error == ENOENT ? name + ": no such file"
                                        : name + ": cannot open the " + kind.name + " (" + std::strerror(error) + ")");
  }
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    throw FileReadError(name + ": cannot examine the " + kind.name + " (" + std::strerror(error) + ")");
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    throw FileReadError(name + ": not a regular file (" + typeName(info.st_mode) + ")");
  }
  size_ = static_cast<std::uintmax_t>(info.st_size);
  if (size_ > kind.maxBytes) {
    ::close(fd_);
    fd_ = -1;
    throw FileReadError(name + ": the " + kind.name + " is " + describeSize(size_) + ", more than the " +
                        describeSize(kind.maxBytes) + " a " + kind.name + " may hold");
  }
  // Reads of a regular file never block; the flag only kept the open from
  // waiting on a FIFO. Cleared all the same, so that reads are plain.
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
}

CheckedFile::~CheckedFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t CheckedFile::read(char* buffer, std::size_t capacity) {
  if (capacity == 0) return 0;
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, capacity);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw FileReadError(printablePath(path_) + ": reading the " + kind_.name + " failed (" + std::strerror(errno) +
                          ")");
    consumed_ += static_cast<std::uintmax_t>(n);
    if (consumed_ > kind_.maxBytes)
      throw FileReadError(printablePath(path_) + ": the " + kind_.name + " grew past the " +
                          describeSize(kind_.maxBytes) + " a " + kind_.name + " may hold while it was read");
    return static_cast<std::size_t>(n);
  }
}

std::string CheckedFile::readAll() {
  // The size fstat gave, plus room to notice growth; never more than the cap + 1.
  std::string text;
  text.resize(static_cast<std::size_t>(std::min<std::uintmax_t>(size_ - std::min(size_, consumed_) + 1,
                                                                kind_.maxBytes + 1)));
  std::size_t filled = 0;
  for (;;) {
    if (filled == text.size()) {
      if (consumed_ > kind_.maxBytes) break;  // read() has thrown already; defensive
      text.resize(static_cast<std::size_t>(std::min<std::uintmax_t>(text.size() * 2 + 4096, kind_.maxBytes + 1)));
    }
    const std::size_t n = read(text.data() + filled, text.size() - filled);
    if (n == 0) break;
    filled += n;
  }
  text.resize(filled);
  return text;
}

std::string readCheckedFile(const std::filesystem::path& path, const FileKind& kind) {
  return CheckedFile(path, kind).readAll();
}

namespace {

void copyMessage(const char* message, CheckedRead& out) {
  std::snprintf(out.error, sizeof out.error, "%s", message);
}

}  // namespace

CheckedRead checkedSize(const char* path, const FileKind& kind) noexcept {
  CheckedRead out;
  try {
    out.size = CheckedFile(path, kind).size();
    out.ok = true;
  } catch (const std::exception& e) {
    copyMessage(e.what(), out);
  }
  return out;
}

CheckedRead readCheckedInto(const char* path, const FileKind& kind, char* buffer, std::size_t capacity) noexcept {
  CheckedRead out;
  try {
    CheckedFile file(path, kind);
    std::size_t filled = 0;
    for (;;) {
      if (filled == capacity) {
        char probe;
        if (file.read(&probe, 1) != 0) {
          copyMessage((printable(path) + ": the " + kind.name + " changed while it was read").c_str(), out);
          return out;
        }
        break;
      }
      const std::size_t n = file.read(buffer + filled, capacity - filled);
      if (n == 0) break;
      filled += n;
    }
    out.size = filled;
    out.ok = true;
  } catch (const std::exception& e) {
    copyMessage(e.what(), out);
  }
  return out;
}

}  // namespace hemiroll::files
