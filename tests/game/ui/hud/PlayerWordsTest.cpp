// game/ui/hud/PlayerWords, WrappedText and HudLayout: what the HUD says and
// where it goes, without a window (issue 27's rough edges 2, 3, 4, 10).
#include "game/ui/hud/PlayerWords.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cctype>
#include <numbers>
#include <string>
#include <vector>

#include "engine/render/Camera.h"
#include "game/ui/hud/HudLayout.h"
#include "game/ui/hud/WrappedText.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
using V = task::TaskVariable;

task::ComponentStatus component(V v, double target, double error, double tolerance) {
  task::ComponentStatus c;
  c.variable = v;
  c.target = target;
  c.error = error;
  c.tolerance = tolerance;
  c.margin = tolerance - std::abs(error);
  c.inside = c.margin >= 0.0;
  return c;
}

std::vector<std::string> rows(const std::vector<task::ComponentStatus>& cs, double heading = 0.0) {
  std::array<AdviceRow, 8> out{};
  const int n = adviceRows(cs, heading, out);
  std::vector<std::string> text;
  for (int i = 0; i < n; ++i) text.emplace_back(out[static_cast<std::size_t>(i)].text.data());
  return text;
}

// The contact point says where to roll, on screen: the paper's target is
// 4 cm back and 4 cm left of the start, which the follow camera shows down
// and to the left; an orbit camera turned a quarter shows it elsewhere.
TEST(PlayerWordsTest, TheContactPointSaysWhereToRollOnScreen) {
  const std::vector<task::ComponentStatus> start = {component(V::u_a, -0.04, 0.04, 0.004),
                                                      component(V::v_a, -0.04, 0.04, 0.004)};
  EXPECT_EQ(rows(start), std::vector<std::string>{"contact point: roll 56.6 mm down-left (±4.0)"});
  // Screen right along +y (and up along -x): the move (-x, -y) is up-left there.
  EXPECT_EQ(rows(start, std::numbers::pi / 2)[0], "contact point: roll 56.6 mm up-left (±4.0)");
  EXPECT_STREQ(screenDirectionWords(1, 0), "right");
  EXPECT_STREQ(screenDirectionWords(0, 1), "up");
  EXPECT_STREQ(screenDirectionWords(-1, 0.2), "left");
  EXPECT_STREQ(screenDirectionWords(-1, -1), "down-left");
  EXPECT_STREQ(screenDirectionWords(0, 0), "nowhere");
}

// The rest in a player's words: no "spin x", "tilt u" or "mass point y",
// no sign to negate; a pair of components is one row.
TEST(PlayerWordsTest, OtherGroupsSayWhatToDo) {
  const std::vector<std::string> r = rows({component(V::x_p, 0.0, 0.009, 0.004), component(V::y_p, 0.0, -0.012, 0.004),
                                           component(V::xd_p, 0.0, -0.1012, 0.01), component(V::w_x, 0.0, 0.1, 0.01),
                                           component(V::w_y, 0.0, 0.0, 0.01), component(V::u_o, 0.0, 0.2, 0.17),
                                           component(V::v_o, 0.0, 0.1, 0.17), component(V::psi, 1.0, -0.5, 0.17)});
  ASSERT_EQ(r.size(), 5u);
  EXPECT_EQ(r[0], "mass point: 15.0 mm off the face's middle, bring it back (±4.0)");
  EXPECT_EQ(r[1], "mass point sliding at 101.2 mm/s: hold it still (±10.0)");
  EXPECT_EQ(r[2], "rolling at 5.73 °/s: let it settle (±0.57)");
  EXPECT_EQ(r[3], "tilted 12.8 °: stand it upright (±9.7)");
  EXPECT_EQ(r[4], "heading: turn it 28.6 ° anticlockwise (±9.7)");
  for (const std::string& line : r)
    for (const char* physics : {"spin x", "tilt u", "mass point y", "off by"}) EXPECT_THAT(line, ::testing::Not(HasSubstr(physics)));
  // Inside every band: said as such.
  EXPECT_EQ(rows({component(V::omega_norm, 0.0, 0.001, 0.01)})[0], "spin: in its band");
}

// The task's short form, from the stage's targets.
TEST(PlayerWordsTest, TheGoalIsTheStagesTargetsInShort) {
  task::StageDef paper;
  for (V v : {V::x_p, V::y_p, V::xd_p, V::yd_p, V::w_x, V::w_y, V::w_z, V::u_a, V::v_a, V::u_o, V::v_o})
    paper.targets.push_back({v, v == V::u_a || v == V::v_a ? -0.04 : 0.0, 0.004});
  EXPECT_EQ(taskGoal(paper, 0, 1),
            "Goal: the contact point onto the green square, then upright, still, the mass point in the middle");
  task::StageDef lean;
  lean.name = "lean";
  lean.targets = {{V::u_o, -0.08, 0.02}};
  lean.hold = 0.5;
  EXPECT_EQ(taskGoal(lean, 0, 2), "Stage 1 of 2 (lean): leaning 5 °; hold 0.5 s");
}

// Wrapped at spaces only, never after a decimal point and never between a
// number and what follows it ("5.\n75 s", "4\ncm" were seen); a word wider
// than the line stands alone.
TEST(PlayerWordsTest, WrappingNeverSplitsANumberFromItsUnit) {
  const auto wrap = [](std::string_view text, float chars) {
    std::vector<std::string> lines;
    wrapLines(text, chars, [](std::string_view s) { return static_cast<float>(s.size()); },
              [&](std::string_view l) { lines.emplace_back(l); });
    return lines;
  };
  EXPECT_EQ(wrap("time 5.75 s and 4 cm", 9), (std::vector<std::string>{"time", "5.75 s", "and 4 cm"}));
  EXPECT_EQ(wrap("mass point speed y off by -101.2 mm/s", 20),
            (std::vector<std::string>{"mass point speed y", "off by -101.2 mm/s"}));
  EXPECT_EQ(wrap("a b c d", 3), (std::vector<std::string>{"a b", "c d"}));
  EXPECT_EQ(wrap("supercalifragilistic word", 5), (std::vector<std::string>{"supercalifragilistic", "word"}));
  EXPECT_EQ(wrap("one\ntwo three", 5), (std::vector<std::string>{"one", "two", "three"}));
  EXPECT_EQ(wrap("fits", 10), (std::vector<std::string>{"fits"}));
  for (const std::string& l : wrap("at 9.10 s: the servo loop stalled for 34 ms, 12 ticks", 12)) {
    EXPECT_NE(l.back(), '.') << l;
    EXPECT_FALSE(std::isdigit(static_cast<unsigned char>(l.back()))) << l;
  }
}

// A panel takes the first free place; the hemisphere's rect is where the
// follow camera draws the ball: about the window's middle, a fifth across.
TEST(PlayerWordsTest, PanelsTakeTheFirstFreePlaceClearOfTheHemisphere) {
  render::RenderScene scene;
  const WindowRect ball = hemisphereRect(scene, 1280, 720);
  EXPECT_NEAR(ball.x + ball.width / 2, 640, 2);
  EXPECT_NEAR(ball.y + ball.height / 2, 360, 30);
  EXPECT_GT(ball.width, 0.18f * 1280);
  EXPECT_LT(ball.width, 0.30f * 1280);
  scene.camera.zoom = 2.0;  // twice as close: twice as large
  EXPECT_NEAR(hemisphereRect(scene, 1280, 720).width, 2 * ball.width, 0.15 * ball.width);
  const WindowRect taken[] = {ball, WindowRect{"hud", 10, 10, 470, 400}};
  const PanelPlace p = firstFreePlace({{500, 10}, {800, 10}, {10, 420}}, 300, 250, taken, 1280, 720);
  EXPECT_EQ(p.x, 800);  // (500, 10) would reach into the ball at y 214
  const PanelPlace none = firstFreePlace({{600, 300}}, 300, 100, taken, 1280, 720);
  EXPECT_EQ(none.x, 600);  // no free place: the first, for the layout tests to name
}

}  // namespace
}  // namespace hemiroll::game
