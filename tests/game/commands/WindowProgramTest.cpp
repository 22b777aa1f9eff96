#include "game/commands/WindowProgram.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "game/commands/ExitCode.h"
#include "tests/support/ProcessRunner.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;

TEST(WindowProgram, LiesBesideTheProgram) {
  EXPECT_EQ(windowProgramBeside("/opt/x/bin/hemiroll"), fs::path("/opt/x/bin/hemiroll-window"));
  EXPECT_EQ(windowProgramBeside("hemiroll"), fs::path("hemiroll-window"));
}

// The built hemiroll hands a window command to the program beside it: its
// usage comes back through the exec, with hemiroll's exit code.
TEST(WindowProgram, HemirollRunsTheWindowCommandsThroughIt) {
  for (const char* command : {"play", "screenshot"}) {
    const test::ProcessResult r = test::runProcess(HEMIROLL_BINARY, {command, "--help"});
    EXPECT_EQ(r.exitCode, kExitOk) << command << ": " << r.err;
    EXPECT_NE(r.out.find(std::string("usage: hemiroll ") + command), std::string::npos) << r.out;
  }
}

// hemiroll copied alone: the headless commands work, a window command says
// which program is missing, where, and how to build it.
TEST(WindowProgram, MissingWindowProgramIsNamedWithItsPath) {
  const test::TempDirectory dir;
  const fs::path alone = dir.path() / "hemiroll";
  fs::copy_file(HEMIROLL_BINARY, alone);
  const test::ProcessResult version = test::runProcess(alone.string(), {"version"});
  EXPECT_EQ(version.exitCode, kExitOk) << version.err;
  for (const char* command : {"play", "screenshot"}) {
    const test::ProcessResult r = test::runProcess(alone.string(), {command, "--help"});
    EXPECT_EQ(r.exitCode, kExitFailure) << command;
    EXPECT_NE(r.err.find("hemiroll " + std::string(command) + ": cannot run the window program " +
                         (dir.path() / "hemiroll-window").string()),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("--target hemiroll-window"), std::string::npos) << r.err;
  }
}

// The window program runs only the window's commands, and says so.
TEST(WindowProgram, RefusesTheHeadlessCommands) {
  const fs::path window = windowProgramBeside(HEMIROLL_BINARY);
  const test::ProcessResult r = test::runProcess(window.string(), {"sweep"});
  EXPECT_EQ(r.exitCode, kExitUsage);
  EXPECT_NE(r.err.find("unknown command 'sweep'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("hemiroll --help"), std::string::npos) << r.err;
}

int throwsRuntimeError(const std::vector<std::string>&) { throw std::runtime_error("the library said no"); }
int throwsBadAlloc(const std::vector<std::string>&) { throw std::bad_alloc(); }
int returnsUsage(const std::vector<std::string>& args) { return args.size() == 1 ? kExitUsage : kExitOk; }

TEST(WindowProgram, GuardTurnsEscapedExceptionsIntoExitOne) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(runCommandGuarded("sim", throwsRuntimeError, {}), kExitFailure);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "hemiroll sim: the library said no\n");
  testing::internal::CaptureStderr();
  EXPECT_EQ(runCommandGuarded("sweep", throwsBadAlloc, {}), kExitFailure);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("hemiroll sweep: out of memory"), std::string::npos);
  EXPECT_EQ(runCommandGuarded("run", returnsUsage, {"x"}), kExitUsage);
  EXPECT_EQ(runCommandGuarded("run", returnsUsage, {}), kExitOk);
}

}  // namespace
}  // namespace hemiroll::game
