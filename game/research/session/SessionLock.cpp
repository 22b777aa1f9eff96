#include "game/research/session/SessionLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "engine/files/PrintableName.h"
#include "engine/record/TrialMeta.h"
#include "game/research/session/SessionError.h"

namespace hemiroll::game {

namespace {

[[noreturn]] void environment(const std::string& message) {
  throw SessionError(SessionError::Kind::Environment, message);
}

// The holder's record: the lock file's first line, at most a few hundred
// bytes (it is written by this class; anything longer is cut).
std::string holderOf(int fd) {
  char text[512];
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  if (n <= 0) return "";
  std::string line(text, static_cast<std::size_t>(n));
  line = line.substr(0, line.find('\n'));
  return files::printable(line);
}

std::string hostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "?";
  return name;
}

}  // namespace

SessionLock::SessionLock(const std::filesystem::path& folder, const std::string& what) {
  const std::filesystem::path path = folder / kLockFile;
  // O_NOFOLLOW: a link in the lock's place is refused, not followed.
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
  if (fd_ < 0)
    environment("cannot open the session lock " + files::printablePath(path) + ": " + std::strerror(errno));
  struct stat info {};
  if (::fstat(fd_, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    environment("the session lock " + files::printablePath(path) + " is not a regular file; move it away");
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string holder = holderOf(fd_);
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK)
      environment("the session folder " + files::printablePath(folder) + " is in use by another session (" +
                  (holder.empty() ? std::string("its holder has not said who it is yet") : holder) +
                  "); wait for it to end, or give another --session");
    environment("cannot lock the session folder " + files::printablePath(folder) + ": " + std::strerror(error));
  }
  // Held. A record left in the file is a holder that ended without
  // releasing it (killed, crashed): its lock went with its process.
  if (const std::string stale = holderOf(fd_); !stale.empty())
    note_ = "took over the session folder's lock from a session that ended without releasing it (" + stale + ")";
  const std::string record = "process " + std::to_string(::getpid()) + " on " + hostName() + ", " + what +
                             ", since " + record::utcTimestamp() + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, record.data(), record.size(), 0) != static_cast<ssize_t>(record.size()))
    environment("cannot write the session lock " + files::printablePath(path) + ": " + std::strerror(errno));
  ::fsync(fd_);
}

SessionLock::~SessionLock() {
  if (fd_ < 0) return;
  // Released cleanly: no record left for the next holder to report.
  if (::ftruncate(fd_, 0) == 0) ::fsync(fd_);
  ::flock(fd_, LOCK_UN);
  ::close(fd_);
}

}  // namespace hemiroll::game
