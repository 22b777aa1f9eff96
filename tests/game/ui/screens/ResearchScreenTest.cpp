// The research flow in a real window under Xvfb, driven by the same
// InputEvents a researcher and a participant make: title -> research (pick
// the protocol) -> session -> trial 1 played by a scripted mouse until its
// time limit -> the break -> trial 2 quit from the pause screen -> the end.
// Then the session folder: manifest, one recorded trial (CSV, sidecar,
// replay) per planned trial and one results row each.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/platform/KeyNames.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/ResultsFile.h"
#include "game/ui/app/App.h"
#include "game/ui/app/ScriptedMouse.h"
#include "game/research/session/SessionManifest.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/ResearchScreen.h"
#include "game/ui/screens/SessionScreen.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void frames(App& app, int n) {
  for (int i = 0; i < n; ++i) app.frame();
}

// Frames until `screen` is on top or `seconds` of wall time passed; the
// scripted mouse plays meanwhile when given.
bool playUntil(App& app, const char* screen, double seconds, ScriptedMouse* mouse = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (std::string(app.topScreen()) == screen) return true;
    if (t > seconds) return false;
    if (mouse) mouse->step(app, t);
    app.frame();
  }
}

// Two blocks of one trial: the first ends at its 1 s time limit, then a
// 0.3 s break, then the second with M2 instead of the level's M3.
constexpr const char* kProtocol = R"lua(
return {
  experiment = "window-test",
  groups = { { name = "solo" } },
  blocks = {
    { level = "tilt.lua", time_limit = 1, instructions = "tilt it",
      break_after = { message = "a short rest", min_duration = 0.3 } },
    { level = "tilt.lua", method = "M2", time_limit = 30 },
  },
}
)lua";

TEST(ResearchScreenTest, AProtocolRunsFromTheResearchScreenIntoItsSessionFolder) {
  test::TempDirectory dir;
  fs::create_directories(dir.path() / "levels" / "protocols");
  dir.write("levels/tilt.lua", readFile(HEMIROLL_SOURCE_DIR "/levels/tutorial_01_tilt_and_return.lua"));
  dir.write("levels/protocols/two.lua", kProtocol);
  dir.write("levels/protocols/broken.lua", "return { experiment = 'b' }");
  setenv("HEMIROLL_DATA_DIR", dir.path().c_str(), 1);
  AppDef def;
  def.hidden = true;
  def.vsync = false;
  def.levelsDir = (dir.path() / "levels").string();
  def.scoresFile = (dir.path() / "scores.sqlite").string();
  App app(def);
  app.settings().participant = "tester";
  frames(app, 3);

  app.inject(platform::keyDownEvent("R"));
  frames(app, 3);
  ASSERT_STREQ(app.topScreen(), "research");
  auto* research = dynamic_cast<ResearchScreen*>(app.screens().top());
  ASSERT_NE(research, nullptr);
  ASSERT_EQ(research->protocols().size(), 2u);
  EXPECT_THAT(research->protocols()[0].error, HasSubstr("broken.lua:1: blocks: missing"));
  app.inject(platform::keyDownEvent("Down"));  // to two.lua
  frames(app, 2);
  EXPECT_THAT(research->status(), HasSubstr("a new session of 2 trials"));
  EXPECT_THAT(research->status(), HasSubstr("; group solo, block order 1 (balanced by arrival: participant 1 of the experiment)"));
  ASSERT_TRUE(research->canStart());

  app.inject(platform::keyDownEvent("Return"));
  frames(app, 3);
  ASSERT_STREQ(app.topScreen(), "session");
  auto* session = dynamic_cast<SessionScreen*>(app.screens().top());
  ASSERT_NE(session, nullptr);
  ASSERT_EQ(session->stage(), SessionScreen::Stage::Ready) << session->error();

  // Trial 1: the scripted mouse takes hold and circles until the time limit.
  app.inject(platform::keyDownEvent("Return"));
  ASSERT_TRUE(playUntil(app, "play", 2.0));
  ScriptedMouse mouse;
  ASSERT_TRUE(playUntil(app, "session", 10.0, &mouse)) << "the trial did not end at its time limit";
  EXPECT_TRUE(mouse.clicked());
  ASSERT_EQ(session->log().size(), 1u);
  EXPECT_THAT(session->log()[0], HasSubstr("trial-001: failure, time limit reached"));
  // The break holds the next trial for its minimum.
  EXPECT_EQ(session->stage(), SessionScreen::Stage::Break);
  app.inject(platform::keyDownEvent("Return"));
  frames(app, 2);
  EXPECT_STREQ(app.topScreen(), "session") << "a trial started during the break";
  const auto breakStart = std::chrono::steady_clock::now();
  while (session->stage() == SessionScreen::Stage::Break &&
         std::chrono::steady_clock::now() - breakStart < std::chrono::seconds(5))
    app.frame();
  ASSERT_EQ(session->stage(), SessionScreen::Stage::Ready);

  // Trial 2: paused and quit, which ends it as a failure that is recorded too.
  app.inject(platform::keyDownEvent("Return"));
  ASSERT_TRUE(playUntil(app, "play", 2.0));
  const auto* play = dynamic_cast<const PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  EXPECT_THAT(play->hud().title(), HasSubstr("trial 2 of 2: "));  // where the player is in the plan
  frames(app, 20);
  app.inject(platform::keyDownEvent("Escape"));
  ASSERT_TRUE(playUntil(app, "pause", 2.0));
  app.inject(platform::keyDownEvent("Q"));
  ASSERT_TRUE(playUntil(app, "session", 5.0));
  ASSERT_EQ(session->log().size(), 2u);
  EXPECT_THAT(session->log()[1], HasSubstr("trial-002: failure, quit by the player"));
  EXPECT_EQ(session->stage(), SessionScreen::Stage::Complete);

  // The folder.
  const fs::path folder = dir.path() / "sessions" / "window-test" / "tester" / "1";
  const SessionManifest m = SessionManifest::fromJson(hemiroll::test::TempDirectory::read(folder / "session.json"), "session.json");
  ASSERT_EQ(m.plan.size(), 2u);
  ASSERT_EQ(m.sittings.size(), 1u);
  EXPECT_EQ(m.sittings[0].player, "mouse");
  const record::ResultsTable results = record::ResultsFile(folder / "results.csv").read();
  ASSERT_EQ(results.rows.size(), 2u);
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(results.columns.begin(), results.columns.end(), name) -
                                    results.columns.begin());
  };
  EXPECT_EQ(results.rows[0][column("trial")], "trial-001");
  EXPECT_EQ(results.rows[0][column("reason")], "time limit reached");
  EXPECT_EQ(results.rows[0][column("method")], "M3");
  EXPECT_EQ(results.rows[1][column("reason")], "quit by the player");
  EXPECT_EQ(results.rows[1][column("method")], "M2");
  EXPECT_EQ(results.rows[1][column("player")], "mouse");
  for (const char* trial : {"trial-001", "trial-002"}) {
    const record::Recording rec = record::RecordingReader::load(folder / (std::string(trial) + ".csv"));
    EXPECT_TRUE(rec.status.complete) << trial;
    EXPECT_EQ(rec.meta.deviceName, "mouse");
    EXPECT_TRUE(rec.status.end->hasTiming) << "a real-time trial carries the loop's timing";
    EXPECT_TRUE(fs::exists(folder / (std::string(trial) + ".replay"))) << trial;
  }
  // Trial 1 ran 1 s of simulated time; rows at the level's record rate.
  const record::Recording first = record::RecordingReader::load(folder / "trial-001.csv");
  EXPECT_NEAR(first.rows.back().time, 1.0, 0.02);
  EXPECT_EQ(first.meta.coupling.method, physics::ForceMethod::M3);
  EXPECT_EQ(record::RecordingReader::load(folder / "trial-002.csv").meta.coupling.method, physics::ForceMethod::M2);

  // Back on the research screen the session shows as complete.
  app.inject(platform::keyDownEvent("Escape"));
  frames(app, 3);
  ASSERT_STREQ(app.topScreen(), "research");
  EXPECT_THAT(research->status(), HasSubstr("this session is complete"));
  EXPECT_FALSE(research->canStart());
}

}  // namespace
}  // namespace hemiroll::game
