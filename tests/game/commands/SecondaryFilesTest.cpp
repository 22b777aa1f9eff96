// Every secondary file the program reads (issue 33, item 3), each replaced
// by what must never hang it or fill its memory: a FIFO (an ordinary open
// waits for a writer for ever), a link to /dev/zero (endless) and a 3 GB
// sparse file (no disk, but 3 GB to a reader that reads whole). Each is
// refused within seconds with a message naming the file, through the very
// code path that reads it: the sidecar and the CSV given to analyze,
// session.json and trial-NNN.json and results.csv when a session resumes,
// sweep.csv.partial when a sweep resumes, a sweep part's CSV and manifest
// when parts merge, a ghost's .hrr and .hrr.time, settings.json.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <future>
#include <thread>

#include "engine/record/RecordError.h"
#include "engine/record/ReplayReader.h"
#include "engine/record/ResultsFile.h"
#include "game/research/analysis/AnalysisInputError.h"
#include "game/research/analysis/TrialLoader.h"
#include "game/ui/settings/SettingsFile.h"
#include "game/research/session/ResearchSession.h"
#include "game/research/session/SessionFolder.h"
#include "game/research/session/SessionResume.h"
#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepManifest.h"
#include "game/research/sweep/SweepMerge.h"
#include "game/trial/GhostFile.h"
#include "tests/game/support/RoseRecording.h"
#include "tests/game/support/TinySweep.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

enum class Hostile { Fifo, DevZero, Sparse };
const char* nameOf(Hostile h) { return h == Hostile::Fifo ? "FIFO" : h == Hostile::DevZero ? "/dev/zero" : "3 GB sparse"; }
constexpr Hostile kAll[] = {Hostile::Fifo, Hostile::DevZero, Hostile::Sparse};
void PrintTo(Hostile h, std::ostream* os) { *os << nameOf(h); }

// Puts the hostile file at `path` (replacing what is there).
void plant(Hostile h, const fs::path& path) {
  std::error_code ec;
  fs::remove(path, ec);
  switch (h) {
    case Hostile::Fifo: ASSERT_EQ(mkfifo(path.c_str(), 0600), 0) << path; break;
    case Hostile::DevZero: fs::create_symlink("/dev/zero", path); break;
    case Hostile::Sparse: {
      std::FILE* f = std::fopen(path.c_str(), "wb");
      ASSERT_NE(f, nullptr);
      std::fclose(f);
      fs::resize_file(path, std::uintmax_t{3} << 30);
      break;
    }
  }
}

// Runs `read` and gives what it threw (or "no error"). A read that hangs
// cannot be cancelled: after 20 s the test program stops, naming the case,
// instead of hanging the suite.
std::string within20s(const std::string& what, const std::function<void()>& read) {
  auto result = std::async(std::launch::async, [&read]() -> std::string {
    try {
      read();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "no error";
  });
  if (result.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
    std::fprintf(stderr, "FATAL: reading %s did not finish within 20 s\n", what.c_str());
    std::_Exit(1);
  }
  return result.get();
}

class SecondaryFilesTest : public ::testing::TestWithParam<Hostile> {
 protected:
  test::TempDirectory dir_;
};

TEST_P(SecondaryFilesTest, AnalyzeRefusesTheSidecarAndTheTrialCsv) {
  const fs::path csv = test::writeRoseRecording(dir_.path(), "trial-001", 50, true);
  fs::path sidecar = csv;
  sidecar.replace_extension(".json");
  plant(GetParam(), sidecar);
  EXPECT_THAT(within20s("a sidecar", [&] { loadTrials({csv.string()}); }), HasSubstr("trial-001.json: "));
  const fs::path given = dir_.path() / "given.csv";
  plant(GetParam(), given);
  EXPECT_THAT(within20s("a trial CSV", [&] { loadTrials({given.string()}); }), HasSubstr("given.csv: "));
}

TEST_P(SecondaryFilesTest, AResumedSessionRefusesItsManifestAndResultsAndSetsAsideABadSidecar) {
  const std::string levels = std::string(HEMIROLL_SOURCE_DIR) + "/levels";
  SessionRequest request;
  request.protocolPath = levels + "/protocols/tutorial_demo.lua";
  request.levelsDir = levels;
  request.participant = "p01";
  request.dataRoot = dir_.path() / "data";
  const fs::path folder = dir_.path() / "data/tutorial-demo/p01/1";
  fs::create_directories(folder);
  plant(GetParam(), folder / kManifestFile);
  EXPECT_THAT(within20s("session.json", [&] { ResearchSession session(request); }), HasSubstr("session.json: "));

  const fs::path trials = dir_.path() / "trials";
  fs::create_directories(trials);
  std::vector<ManifestTrial> plan(1);
  plan[0].trialId = sessionTrialId(1);
  plan[0].index = 1;
  plant(GetParam(), trials / "results.csv");
  EXPECT_THAT(within20s("results.csv", [&] { findResumePoint(trials, plan); }), HasSubstr("results.csv: "));
  EXPECT_THAT(within20s("results.csv", [&] { record::ResultsFile(trials / "results.csv").read(); }),
              HasSubstr("results.csv: "));
  fs::remove(trials / "results.csv");
  // A sidecar that cannot be read is an interrupted trial: found, not read.
  test::writeRoseRecording(trials, "trial-001", 10, true);
  plant(GetParam(), trials / "trial-001.json");
  ResumePoint point;
  EXPECT_EQ(within20s("trial-001.json", [&] { point = findResumePoint(trials, plan); }), "no error");
  ASSERT_EQ(point.interrupted.size(), 1u);
  EXPECT_EQ(point.interrupted[0].first, "trial-001");
}

TEST_P(SecondaryFilesTest, SweepsRefuseAPartialFileAPartAndAManifest) {
  const fs::path out = dir_.path() / "out";
  const SweepPartReport first = test::runSweepInto(test::kTinySweep, out, {0, 3});
  // Make the part look interrupted, with the hostile file as its rows so far.
  std::string manifest = test::TempDirectory::read(first.manifest);
  const std::size_t complete = manifest.find("true", manifest.find("\"complete\""));
  ASSERT_NE(complete, std::string::npos);
  manifest.replace(complete, 4, "false");
  dir_.write("out/" + first.manifest.filename().string(), manifest);
  fs::path partial = first.csv;
  partial += ".partial";
  plant(GetParam(), partial);
  EXPECT_THAT(within20s("sweep.csv.partial", [&] { test::runSweepInto(test::kTinySweep, out, {0, 3}); }),
              HasSubstr(".csv.partial: "));

  const fs::path parts = dir_.path() / "parts";
  const SweepPartReport part = test::runSweepInto(test::kTinySweep, parts, {1, 3});
  plant(GetParam(), part.csv);
  EXPECT_THAT(within20s("a part's CSV", [&] { mergeSweepParts({parts}); }),
              HasSubstr(part.csv.filename().string() + ": "));
  plant(GetParam(), part.manifest);
  EXPECT_THAT(within20s("a part's manifest", [&] { readManifest(part.manifest); }),
              HasSubstr(part.manifest.filename().string() + ": "));
}

TEST_P(SecondaryFilesTest, AGhostsLogAndTimeAndTheSettingsAreRefused) {
  const fs::path ghost = dir_.path() / "level.hrr";
  plant(GetParam(), ghost);
  EXPECT_THAT(within20s("a ghost", [&] { record::ReplayReader::load(ghost); }), HasSubstr("level.hrr: "));
  plant(GetParam(), dir_.path() / "level.hrr.time");
  std::optional<double> time = 1.0;
  EXPECT_EQ(within20s("a ghost's time", [&] { time = ghostTime(ghost); }), "no error");
  EXPECT_FALSE(time.has_value());  // no time shown, nothing else

  const fs::path settings = dir_.path() / "settings.json";
  plant(GetParam(), settings);
  LoadedSettings loaded;
  EXPECT_EQ(within20s("settings.json", [&] { loaded = loadSettings(settings); }), "no error");
  ASSERT_FALSE(loaded.notes.empty());
  EXPECT_THAT(loaded.notes[0], HasSubstr("is not a file of at most 1 MiB"));
}

INSTANTIATE_TEST_SUITE_P(Hostile, SecondaryFilesTest, ::testing::ValuesIn(kAll),
                         [](const ::testing::TestParamInfo<Hostile>& info) {
                           return std::string(info.param == Hostile::Fifo      ? "Fifo"
                                              : info.param == Hostile::DevZero ? "DevZero"
                                                                               : "Sparse3GB");
                         });

}  // namespace
}  // namespace hemiroll::game
