#pragma once
// Runs a program as a child process and collects its exit code, stdout and
// stderr, so that tests exercise the real `hemiroll` binary end to end.

#include <string>
#include <vector>

namespace hemiroll::test {

struct ProcessResult {
  int exitCode = -1;  // -1 if the child did not exit normally (signal)
  std::string out;    // stdout
  std::string err;    // stderr
};

ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args);

}  // namespace hemiroll::test
