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
  // Whether opening syncs the directory, so that the file's entry survives a
  // power cut with the data its flushes sync (fdatasync syncs the file, not
  // the entry naming it).
  enum class Entry {
    Sync,
    // The caller makes the entry durable itself: a temporary file that is
    // renamed and the rename synced (writeFileAtomically), or a file whose
    // entry a rename and directory sync have just made durable.
    AlreadyCovered,
  };

  // mode as fopen ("wb", "ab"; "wbx" refuses an existing file). Throws
  // RecordError naming the file.
  DurableFile(const std::filesystem::path& path, const char* mode, Entry entry = Entry::Sync);
  ~DurableFile();
  DurableFile(const DurableFile&) = delete;
  DurableFile& operator=(const DurableFile&) = delete;

  // False after any failed write, flush or sync (error() says which).
  bool write(std::string_view bytes);
  bool writeAt(long offset, const void* bytes, std::size_t size);  // then back to the end
  bool flush();  // fflush + fdatasync; nothing when nothing was written since the last one
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
  // Bytes may be in the stdio buffer or the page cache only: true from the
  // open (an "ab" file may hold data not yet synced) until a flush succeeds.
  bool unsynced_ = true;
};

// Whether a replacement is durable when writeFileAtomically returns (the
// directory synced after the rename), or atomic only: a later sync of the same
// directory (another replacement's, moveFileDurably's) makes it durable, and
// the caller says why nothing needs it durable before then.
enum class DirectorySync { Now, Deferred };

// Replaces path's content atomically. Throws RecordError naming the file.
void writeFileAtomically(const std::filesystem::path& path, std::string_view content,
                         DirectorySync sync = DirectorySync::Now);
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
