#pragma once
// File writing that survives a killed process and, as far as the kernel
// allows, a power cut: a stdio stream with flush = fflush + fdatasync, and a
// whole-file replacement that is atomic (temp file, fsync, rename, fsync of
// the directory) so a reader sees the old file or the new one, never a mix.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "engine/files/FileKinds.h"

namespace hemiroll::record {

class DurableFile {
 public:
  // mode as fopen ("wb", "ab"; "wbx" refuses an existing file). Throws
  // RecordError naming the file.
  DurableFile(const std::filesystem::path& path, const char* mode);
  ~DurableFile();
  DurableFile(const DurableFile&) = delete;
  DurableFile& operator=(const DurableFile&) = delete;

  // False after any failed write, flush or sync (error() says which).
  bool write(std::string_view bytes);
  bool writeAt(long offset, const void* bytes, std::size_t size);  // then back to the end
  bool flush();  // fflush + fdatasync
  bool close();  // flush + fclose
  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  void fail(const char* what);

  std::filesystem::path path_;
  static constexpr std::size_t kBufferSize = std::size_t{1} << 20;
  std::unique_ptr<char[]> buffer_;  // stdio's buffer; outlives file_ (closed in the destructor's body)
  std::FILE* file_ = nullptr;
  std::string error_;
};

// Replaces path's content atomically. Throws RecordError naming the file.
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);
// Renames `from` to `to` (replacing it) and syncs the directory: a file
// written and flushed under a temporary name becomes durable under its own.
// Throws RecordError.
void moveFileDurably(const std::filesystem::path& from, const std::filesystem::path& to);
// Appends in one write() and fsyncs (O_APPEND). Throws RecordError.
void appendDurably(const std::filesystem::path& path, std::string_view content);
// The whole file as bytes, read through the checked reader (engine/files:
// a regular file within `kind`'s cap). Throws RecordError naming it.
std::string readWholeFile(const std::filesystem::path& path, const files::FileKind& kind);

}  // namespace hemiroll::record
