#pragma once
// One session at a time in a session folder. Two `hemiroll session`
// processes on one folder (issue 33) each took the other's running trial for
// an interrupted one: the second moved the first's files aside and ran the
// trial again, results.csv listed it twice, and a later run called the
// session complete.
//
// The lock is flock(2) on <folder>/session.lock, held for as long as the
// session runs. The kernel releases it when its process ends, however it
// ends (kill -9 included), so a lock is never left behind by a dead
// process; what is left is the file's text (who held it: pid, host, start
// time), which the next holder reads and reports as a stale lock taken over.
// A clean release empties the file. The file stays: removing it would let a
// third process lock a new file while a second still waits on the old one.

#include <filesystem>
#include <string>

namespace hemiroll::game {

inline constexpr const char* kLockFile = "session.lock";

class SessionLock {
 public:
  // Takes the folder's lock (the folder must exist). Throws SessionError
  // (Environment) naming the holder when another process holds it, or when
  // the lock file cannot be opened.
  SessionLock(const std::filesystem::path& folder, const std::string& what);
  ~SessionLock();
  SessionLock(const SessionLock&) = delete;
  SessionLock& operator=(const SessionLock&) = delete;

  // "" or one sentence: the stale lock of a process that ended without
  // releasing it, taken over.
  const std::string& note() const { return note_; }

 private:
  int fd_ = -1;
  std::string note_;
};

}  // namespace hemiroll::game
