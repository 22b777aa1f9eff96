// kill -9 in the middle of a trial: a finished trial stays intact and the
// interrupted one keeps everything but its last moments.
//
// The rows reach the kernel only when the recorder flushes (its 1 MiB stdio
// buffer never fills in 0.5 s here), so this checks the interval flush.
//
// The bound: the writer drains the ring every pollInterval (5 ms) and
// flushes (fflush: the rows reach the kernel, which keeps them when the
// process dies; fdatasync: the disk) every flushInterval (0.5 s). Rows still
// in the ring or in stdio's buffer die with the process, so at most
// flushInterval + pollInterval ~ 0.51 s is lost; the test allows 1 s, the
// brief's promise, leaving ~0.5 s for a loaded machine's scheduling delays.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordingReader.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::record {
namespace {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

TEST(TrialRecorderCrashTest, KillNineLosesAtMostTheLastSecondAndNoFinishedTrial) {
  hemiroll::test::TempDirectory dir;
  const std::string helper = RECORD_CRASH_HELPER;
  const std::string folder = dir.path().string();
  std::fflush(nullptr);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    execl(helper.c_str(), helper.c_str(), folder.c_str(), "3", static_cast<char*>(nullptr));
    _exit(127);
  }
  // The interrupted trial's CSV appears when its recording starts.
  const auto csv = dir.path() / "interrupted.csv";
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!std::filesystem::exists(csv) && std::chrono::steady_clock::now() < giveUp)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const bool started = std::filesystem::exists(csv);
  // 2.45 s: just before the fifth 0.5 s flush after the recorder opened,
  // near the worst case (a kill just after a flush would lose almost nothing).
  if (started) std::this_thread::sleep_for(std::chrono::milliseconds(2450));
  const double killedAt = steadySeconds();
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(started) << "the helper never began the second trial";
  ASSERT_TRUE(WIFSIGNALED(status)) << "the helper ended before the kill (exit " << WEXITSTATUS(status) << ")";

  // The finished trial: complete, every row, its results row.
  const Recording finished = RecordingReader::load(dir.path() / "finished.csv");
  EXPECT_TRUE(finished.status.complete);
  EXPECT_EQ(finished.rows.size(), 300u);
  EXPECT_EQ(finished.status.end->outcome, "success");
  const std::string results = hemiroll::test::TempDirectory::read(dir.path() / "results.csv");
  EXPECT_EQ(std::count(results.begin(), results.end(), '\n'), 2) << results;

  // The interrupted trial: parses up to its last complete line, says it is
  // incomplete, has no gap, and reaches to within 1 s of the kill.
  ReadOptions lenient;
  lenient.allowTruncatedTail = true;
  const Recording cut = RecordingReader::load(csv, lenient);
  EXPECT_FALSE(cut.status.complete);
  ASSERT_FALSE(cut.rows.empty());
  for (std::size_t i = 0; i < cut.rows.size(); ++i) {
    ASSERT_EQ(cut.rows[i].tick, i + 1);
    ASSERT_EQ(cut.rows[i].state[0], static_cast<double>(i + 1));
  }
  const double lost = killedAt - cut.rows.back().time;
  EXPECT_GE(lost, 0.0);
  EXPECT_LE(lost, 1.0) << cut.rows.size() << " rows kept";
  std::printf("[ measured ] kill -9 after %zu rows: the last row on disk was %.3f s before the kill\n",
              cut.rows.size(), lost);
}

}  // namespace
}  // namespace hemiroll::record
