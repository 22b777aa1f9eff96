#include "engine/record/DurableFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

namespace {

std::string systemError(const std::filesystem::path& path, const char* what) {
  return path.string() + ": " + what + ": " + std::strerror(errno);
}

// Makes a rename or a new file itself durable: the directory entry lives in
// the directory, which has its own data to sync.
void syncDirectory(const std::filesystem::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // best effort: some file systems refuse; the data is synced already
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

DurableFile::DurableFile(const std::filesystem::path& path, const char* mode, Entry entry) : path_(path) {
  file_ = std::fopen(path.c_str(), mode);
  if (file_ == nullptr)
    throw RecordError(errno == EEXIST ? path.string() + ": already exists (a recording is never overwritten)"
                                      : systemError(path, "cannot open for writing"));
  // 1 MiB: more than a second of rows even at 1 kHz, so data reaches the
  // kernel when flush() says so (the recorders' interval), predictably, in
  // few large writes - not whenever a small default buffer happens to fill.
  // (glibc ignores the size unless it is given the buffer.) Left
  // uninitialised: stdio writes before it reads, and zeroing it touched all
  // 256 of its pages (a page fault each) for every file, even a manifest of
  // a few hundred bytes (issue 32: ~700 of a sweep's 2 000 faults).
  buffer_ = std::make_unique_for_overwrite<char[]>(kBufferSize);
  std::setvbuf(file_, buffer_.get(), _IOFBF, kBufferSize);
  if (entry == Entry::Sync) syncDirectory(path.parent_path());
}

DurableFile::~DurableFile() { close(); }

void DurableFile::fail(const char* what) {
  if (error_.empty()) error_ = systemError(path_, what);
}

bool DurableFile::write(std::string_view bytes) {
  if (file_ == nullptr) return false;
  unsynced_ = true;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail("write failed");
  return ok();
}

bool DurableFile::writeAt(long offset, const void* bytes, std::size_t size) {
  if (file_ == nullptr) return false;
  unsynced_ = true;
  if (std::fseek(file_, offset, SEEK_SET) != 0 || std::fwrite(bytes, 1, size, file_) != size ||
      std::fseek(file_, 0, SEEK_END) != 0)
    fail("write failed");
  return ok();
}

bool DurableFile::flush() {
  if (file_ == nullptr) return false;
  // Nothing written since the last successful flush: the stdio buffer is
  // empty and every byte through this descriptor is on disk already, so
  // another fdatasync would sync nothing but still wait on the disk (close()
  // after a final flush, a recorder's idle interval).
  if (!unsynced_) return ok();
  if (std::fflush(file_) != 0) fail("flush failed");
  else if (::fdatasync(::fileno(file_)) != 0) fail("fdatasync failed");
  else unsynced_ = false;
  return ok();
}

bool DurableFile::close() {
  if (file_ == nullptr) return ok();
  flush();
  if (std::fclose(file_) != 0) fail("close failed");
  file_ = nullptr;
  return ok();
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view content, DirectorySync sync) {
  std::filesystem::path temp = path;
  temp += ".tmp";
  // The temporary file never outlives a failure: a folder in the target's
  // place (sweep map --out DIR) left DIR.tmp behind.
  std::string error;
  {
    // Its entry needs no sync of its own: a crash before the rename leaves
    // the old file under `path` (the temporary one, whole, cut or gone, is
    // read by nobody and truncated by the next attempt); after it, the sync
    // of the directory below makes the new name durable with the rename.
    DurableFile out(temp, "wb", DurableFile::Entry::AlreadyCovered);
    out.write(content);
    if (!out.close()) error = out.error();
  }
  if (error.empty() && std::rename(temp.c_str(), path.c_str()) != 0) error = systemError(path, "cannot replace");
  if (!error.empty()) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw RecordError(error);
  }
  if (sync == DirectorySync::Now) syncDirectory(path.parent_path());
}

void moveFileDurably(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) throw RecordError(systemError(to, "cannot replace"));
  syncDirectory(to.parent_path());
}

void appendDurably(const std::filesystem::path& path, std::string_view content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw RecordError(systemError(path, "cannot open for appending"));
  // One write(): with O_APPEND the row lands whole at the end (a short write
  // only on a full disk, reported).
  const ssize_t n = ::write(fd, content.data(), content.size());
  const bool written = n == static_cast<ssize_t>(content.size());
  const bool synced = written && ::fsync(fd) == 0;
  const std::string error = written ? (synced ? "" : systemError(path, "fsync failed")) : systemError(path, "write failed");
  ::close(fd);
  if (!error.empty()) throw RecordError(error);
}

std::string readWholeFile(const std::filesystem::path& path, const files::FileKind& kind) {
  try {
    return files::readCheckedFile(path, kind);
  } catch (const files::FileReadError& e) {
    throw RecordError(e.what());
  }
}

}  // namespace hemiroll::record
