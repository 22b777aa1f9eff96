#include "tests/support/ProcessRunner.h"

#include "tests/support/ChildProcess.h"

namespace hemiroll::test {

// A child that runs to its end: ChildProcess, waited for at once.
ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args) {
  ChildProcess child(program, args);
  ProcessResult result;
  result.exitCode = child.wait();
  result.out = child.out();
  result.err = child.err();
  return result;
}

}  // namespace hemiroll::test
