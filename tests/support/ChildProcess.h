#pragma once
// A child process that runs alongside the test (runProcess waits for its
// child; this one does not): start it, signal it, then collect its exit and
// stdout. For end-to-end tests of programs that talk to the test over a
// socket (the UDP bridge's reference client).

#include <string>
#include <sys/types.h>
#include <vector>

namespace hemiroll::test {

class ChildProcess {
 public:
  // Starts program with args; stdout and stderr go to temporary files.
  // Throws std::runtime_error if it cannot fork.
  ChildProcess(const std::string& program, const std::vector<std::string>& args);
  // Kills (SIGKILL) and reaps a child still running, removes the files.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  void signal(int sig);
  // Waits for the exit; the exit code, or -1 when a signal ended it.
  int wait();
  bool running();
  std::string out() const;  // stdout so far
  std::string err() const;  // stderr so far

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
  int exitCode_ = -1;
  std::string outPath_, errPath_;
};

}  // namespace hemiroll::test
