#include "game/ui/screens/ScreenStack.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/platform/KeyNames.h"
#include "game/ui/app/App.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

// A screen that logs its hooks ("name:enter", "name:leave").
class LoggingScreen final : public Screen {
 public:
  LoggingScreen(App& app, std::string name, std::vector<std::string>& log, bool overlay = false)
      : Screen(app), name_(std::move(name)), log_(log), overlay_(overlay) {}
  ~LoggingScreen() override { log_.push_back(name_ + ":destroyed"); }
  const char* name() const override { return name_.c_str(); }
  void enter() override { log_.push_back(name_ + ":enter"); }
  void leave() override { log_.push_back(name_ + ":leave"); }
  void paint() override {}
  bool overlay() const override { return overlay_; }

 private:
  std::string name_;
  std::vector<std::string>& log_;
  bool overlay_;
};

TEST(ScreenStackTest, ChangesWaitForApplyAndCallTheHooksInOrder) {
  test::TempDirectory dir;
  AppDef def;
  def.hidden = true;
  def.scoresFile = (dir.path() / "s.sqlite").string();
  def.settingsFile = (dir.path() / "settings.json").string();  // not the user's
  App app(def);  // its own stack holds the title; this test uses a fresh one
  std::vector<std::string> log;
  ScreenStack stack;
  stack.push(std::make_unique<LoggingScreen>(app, "a", log));
  EXPECT_TRUE(stack.empty());  // not before apply()
  stack.apply();
  stack.push(std::make_unique<LoggingScreen>(app, "b", log, true));
  stack.apply();
  ASSERT_EQ(stack.size(), 2u);
  EXPECT_STREQ(stack.top()->name(), "b");
  // An overlay shows the screen below it too.
  std::vector<Screen*> visible;
  stack.visible(visible);
  ASSERT_EQ(visible.size(), 2u);
  EXPECT_STREQ(visible[0]->name(), "a");
  stack.replace(std::make_unique<LoggingScreen>(app, "c", log));
  stack.apply();
  stack.visible(visible);
  EXPECT_EQ(visible.size(), 1u);  // c is opaque
  stack.pop();
  stack.apply();
  EXPECT_STREQ(stack.top()->name(), "a");
  const std::vector<std::string> expected = {"a:enter", "a:leave",  "b:enter", "b:leave", "b:destroyed",
                                             "c:enter", "c:leave",  "c:destroyed", "a:enter"};
  EXPECT_EQ(log, expected);
  stack.reset(nullptr);
  stack.apply();
  EXPECT_TRUE(stack.empty());
}

TEST(ScreenStackTest, TheAppStartsOnTheTitleAndQuitsOnEscape) {
  test::TempDirectory dir;
  AppDef def;
  def.hidden = true;
  def.scoresFile = (dir.path() / "s.sqlite").string();
  def.settingsFile = (dir.path() / "settings.json").string();  // not the user's
  App app(def);
  EXPECT_STREQ(app.topScreen(), "title");
  EXPECT_TRUE(app.frame());
  app.inject(platform::keyDownEvent("Escape"));
  app.frame();
  EXPECT_FALSE(app.frame());
}

}  // namespace
}  // namespace hemiroll::game
