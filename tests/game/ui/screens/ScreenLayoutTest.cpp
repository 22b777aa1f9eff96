// The window's layout rules (issue 27) on every screen a player meets, at
// the window sizes players use, 1280x720 and 1920x1080, in a real window
// (Xvfb + llvmpipe): every panel inside the window, no text cut (wrapped
// instead), and no panel over the hemisphere while it is on screen (play,
// pause, results, replay). The play screens are the hard cases: the paper's
// task with four and more groups out of their bands and the full table on,
// and a tutorial with its message and take-hold prompt; the title with its
// "no sound" note, the pause panel with a safety stop's long sentence.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <string>

#include "engine/platform/KeyNames.h"
#include "game/ui/app/App.h"
#include "game/ui/app/ScriptedMouse.h"
#include "game/ui/hud/HudLayout.h"
#include "game/ui/screens/PauseScreen.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/ReplayScreen.h"
#include "game/ui/screens/ResultsScreen.h"
#include "game/ui/screens/ScreenStack.h"
#include "tests/game/ui/support/HiddenApp.h"
#include "tests/game/ui/support/LayoutAudit.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using namespace std::chrono_literals;

struct WindowSize {
  int width, height;
};
void PrintTo(const WindowSize& s, std::ostream* out) { *out << s.width << "x" << s.height; }

class ScreenLayoutTest : public ::testing::TestWithParam<WindowSize> {
 protected:
  void SetUp() override {
    def_ = test::hiddenAppIn(dir_.path());
    def_.width = GetParam().width;
    def_.height = GetParam().height;
    def_.levelsDir = HEMIROLL_SOURCE_DIR "/levels";
  }
  float w() const { return static_cast<float>(GetParam().width); }
  float h() const { return static_cast<float>(GetParam().height); }
  // Two frames: auto-sized windows take their size in their second.
  void settle(App& app, int frames = 3) {
    for (int i = 0; i < frames; ++i) app.frame();
  }
  // ImGui sizes an auto-resizing panel to the content of the frame before,
  // so a panel whose content grows this frame (a component leaving its
  // band, a line wrapping anew, a late-tick note on a busy machine) is cut
  // for that one frame and fits in the next: 16 ms no player sees. A cut
  // that lasts is the layout fault, so a problem is reported only when the
  // same window has the same kind of problem in kFramesChecked frames in a
  // row (the first is the frame already drawn).
  static constexpr int kFramesChecked = 3;
  static std::string problemKind(const std::string& problem) {
    const std::string window = problem.substr(0, problem.find("' at") + 1);
    for (const char* kind : {"px wide", "px tall", "is not inside", "covers the hemisphere"})
      if (problem.find(kind) != std::string::npos) return window + " " + kind;
    return problem;
  }
  void expectClean(App& app, const char* screen, const WindowRect* keepClear = nullptr) {
    std::map<std::string, int> framesWith;
    std::vector<std::string> problems;
    for (int frame = 0; frame < kFramesChecked; ++frame) {
      if (frame > 0) app.frame();
      problems = test::layoutProblems(w(), h(), keepClear);
      for (const std::string& p : problems) ++framesWith[problemKind(p)];
    }
    std::string all;
    for (const std::string& p : problems)
      if (framesWith[problemKind(p)] == kFramesChecked) all += "\n  " + p;
    EXPECT_TRUE(all.empty()) << screen << ":" << all << "\nwindows drawn: "
                             << ::testing::PrintToString(test::drawnWindows());
  }
  // Circles of 5 mm (20 px at 0.25 mm/px): enough to put rolling, tilt,
  // the mass point and its speed out of the paper's bands in a second.
  void playFor(App& app, std::chrono::duration<double> d) {
    ScriptedMouse mouse({.clickAt = 0.3, .radius = 20.0, .period = 1.5});
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (t >= d.count()) break;
      mouse.step(app, t);
      app.frame();
    }
  }
  test::TempDirectory dir_;
  AppDef def_;
};

TEST_P(ScreenLayoutTest, MenusWrapTheirTextInsideTheWindow) {
  // No sound device: the title's note is the long "no sound: ..." sentence
  // that was cut at its panel's edge.
  setenv("SDL_AUDIODRIVER", "no-such-driver", 1);
  App app(def_);
  setenv("SDL_AUDIODRIVER", "dummy", 1);
  ASSERT_FALSE(app.notes().empty()) << "no note to lay out";
  settle(app);
  EXPECT_STREQ(app.topScreen(), "title");
  expectClean(app, "title");
  app.inject(platform::keyDownEvent("S"));
  settle(app);
  EXPECT_STREQ(app.topScreen(), "settings");
  expectClean(app, "settings");
  app.inject(platform::keyDownEvent("Escape"));
  settle(app);
  app.inject(platform::keyDownEvent("Return"));
  settle(app);
  EXPECT_STREQ(app.topScreen(), "levels");
  expectClean(app, "levels");
}

// The paper's task played for a while by a scripted mouse: rolling, tilt,
// the mass point and its speed all out of their bands at once (the case
// whose panel grew over the hemisphere), then the full table, a pause after
// a safety stop, the results and the replay.
TEST_P(ScreenLayoutTest, PlayPauseResultsAndReplayKeepTheHemisphereInView) {
  App app(def_);
  app.screens().push(std::make_unique<PlayScreen>(app, HEMIROLL_SOURCE_DIR "/levels/paper_reaching.lua"));
  settle(app);
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();
  const WindowRect ball = play->hud().keepClear();
  // The hemisphere stands about the middle, a fifth of the width across or more.
  EXPECT_NEAR(ball.x + ball.width / 2, w() / 2, w() * 0.02f);
  EXPECT_GT(ball.width, w() * 0.15f);
  expectClean(app, "play, before taking hold", &ball);

  playFor(app, 2.5s);
  settle(app);
  int out = 0;
  for (const AdviceRow& row : play->hud().adviceRows()) out += !row.inside;
  EXPECT_GE(out, 4) << "the hard case needs four groups or more out of their bands";
  expectClean(app, "play, many out", &play->hud().keepClear());
  app.inject(platform::keyDownEvent("I"));  // the full table
  settle(app);
  ASSERT_TRUE(play->hud().fullTable());
  expectClean(app, "play, full table", &play->hud().keepClear());

  // The pause screen as a safety stop shows it: its longest sentence.
  play->session()->pause();
  app.screens().push(std::make_unique<PauseScreen>(
      app, *play,
      "Safety stop: servo loop stalled. The force is off and the hemisphere waits where it is. Continue, then take "
      "hold again (click or Space) to play on."));
  settle(app);
  EXPECT_STREQ(app.topScreen(), "pause");
  expectClean(app, "pause", &play->hud().keepClear());

  app.inject(platform::keyDownEvent("Q"));
  settle(app, 4);
  auto* results = dynamic_cast<ResultsScreen*>(app.screens().top());
  ASSERT_NE(results, nullptr) << app.topScreen();
  const WindowRect endBall = hemisphereRect(results->ending().scene, w(), h());
  expectClean(app, "results", &endBall);

  app.inject(platform::keyDownEvent("W"));
  settle(app, 10);
  auto* replay = dynamic_cast<ReplayScreen*>(app.screens().top());
  ASSERT_NE(replay, nullptr) << app.topScreen();
  EXPECT_EQ(replay->error(), "");
  expectClean(app, "replay", &endBall);
}

// A tutorial with a message, three plots and the take-hold prompt, then
// letting go (the prompt says how to go on): every panel placed clear of
// the hemisphere and of each other.
TEST_P(ScreenLayoutTest, MessagesAndPromptsFindAFreePlace) {
  App app(def_);
  app.screens().push(std::make_unique<PlayScreen>(app, HEMIROLL_SOURCE_DIR "/levels/tutorial_03_precess.lua"));
  settle(app);
  auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
  ASSERT_NE(play, nullptr);
  ASSERT_NE(play->session(), nullptr) << play->error();
  EXPECT_THAT(play->hud().prompt(), ::testing::HasSubstr("to take hold"));
  EXPECT_FALSE(play->hud().messages(0.0).empty());
  expectClean(app, "tutorial 3, waiting", &play->hud().keepClear());
  playFor(app, 1.0s);
  app.inject(platform::keyDownEvent("Backspace"));
  settle(app);
  EXPECT_THAT(play->hud().prompt(), ::testing::HasSubstr("take hold again"));
  expectClean(app, "tutorial 3, let go", &play->hud().keepClear());
}

// The audit itself: a panel of fixed width with a line longer than it, and
// one over the window's middle, are both found (else the checks above could
// pass on a layout they do not see).
class CutPanel final : public Screen {
 public:
  using Screen::Screen;
  const char* name() const override { return "cut"; }
  void paint() override {
    ImGui::SetNextWindowPos(ImVec2(10, 10));
    ImGui::SetNextWindowSize(ImVec2(200, 60));
    ImGui::Begin("too narrow", nullptr, ImGuiWindowFlags_NoDecoration);
    ImGui::TextUnformatted("a line far longer than the two hundred pixels of its panel");
    ImGui::End();
  }
};

TEST_P(ScreenLayoutTest, TheAuditFindsCutTextAndPanelsOverTheHemisphere) {
  App app(def_);
  app.screens().push(std::make_unique<CutPanel>(app));
  settle(app);
  const WindowRect middle{"hemisphere", 100, 0, 100, 100};  // under the panel
  const std::vector<std::string> problems = test::layoutProblems(w(), h(), &middle);
  ASSERT_EQ(problems.size(), 2u) << ::testing::PrintToString(problems);
  EXPECT_THAT(problems[0], ::testing::HasSubstr("'too narrow' at 10,10 200x60 cuts its text"));
  EXPECT_THAT(problems[1], ::testing::HasSubstr("covers the hemisphere"));
}

INSTANTIATE_TEST_SUITE_P(PlayersWindows, ScreenLayoutTest,
                         ::testing::Values(WindowSize{1280, 720}, WindowSize{1920, 1080}),
                         [](const auto& info) {
                           return std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
                         });

}  // namespace
}  // namespace hemiroll::game
