#include "game/commands/PlayCommand.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "tests/support/ProcessRunner.h"

namespace hemiroll::game {
namespace {

TEST(PlayCommandTest, DefaultsAndFlags) {
  PlayOptionsResult r = parsePlayOptions({});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.level, "");
  EXPECT_EQ(r.options.width, 1280);
  EXPECT_EQ(r.options.height, 720);
  EXPECT_TRUE(r.options.vsync);
  r = parsePlayOptions({"levels/x.lua", "--size", "800x600", "--no-vsync", "--autoplay", "2.5", "--levels", "L"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.level, "levels/x.lua");
  EXPECT_EQ(r.options.width, 800);
  EXPECT_EQ(r.options.height, 600);
  EXPECT_FALSE(r.options.vsync);
  EXPECT_EQ(r.options.autoplay, 2.5);
  EXPECT_EQ(r.options.levelsDir, "L");
}

TEST(PlayCommandTest, BadFlagsSayWhatIsWrong) {
  EXPECT_NE(parsePlayOptions({"--size", "800"}).error.find("--size"), std::string::npos);
  EXPECT_NE(parsePlayOptions({"--size", "10x10"}).error.find("--size"), std::string::npos);
  EXPECT_NE(parsePlayOptions({"--autoplay", "nan", "l.lua"}).error.find("--autoplay"), std::string::npos);
  EXPECT_NE(parsePlayOptions({"--autoplay", "3"}).error.find("needs a LEVEL"), std::string::npos);
  EXPECT_NE(parsePlayOptions({"--bogus"}).error.find("unknown flag '--bogus'"), std::string::npos);
  EXPECT_NE(parsePlayOptions({"a.lua", "b.lua"}).error.find("unexpected argument 'b.lua' (only one level)"), std::string::npos);
  EXPECT_NE(parsePlayOptions({"--levels"}).error.find("needs a value"), std::string::npos);
}

// No display: one message saying how to run headless, exit 2, whether the
// game is asked for by name or by running hemiroll with no command.
TEST(PlayCommandTest, NoDisplayGivesTheHeadlessWaysAndExitCode2) {
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  unsetenv("SDL_VIDEODRIVER");
  for (const std::vector<std::string>& args : {std::vector<std::string>{"play"}, std::vector<std::string>{}}) {
    const test::ProcessResult r = test::runProcess(HEMIROLL_BINARY, args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("hemiroll run LEVEL.lua --bot BOT.lua"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("hemiroll sim"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("xvfb-run -a make play"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  }
}

// A level that is not there: named, with where else it was looked for, and
// exit 2 before any window (so also without a display, and under --autoplay,
// whose window would never show the loader's words).
TEST(PlayCommandTest, AMissingLevelIsNamedBeforeAnyWindow) {
  unsetenv("DISPLAY");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"play", "no_such_level.lua"},
        std::vector<std::string>{"play", "no_such_level.lua", "--autoplay", "1", "--levels", "."}}) {
    const test::ProcessResult r = test::runProcess(HEMIROLL_BINARY, args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("no level file 'no_such_level.lua'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("no display"), std::string::npos) << r.err;
  }
  const test::ProcessResult r = test::runProcess(HEMIROLL_BINARY, {"play", "no_such_level.lua", "--levels", "."});
  EXPECT_NE(r.err.find("(nor one of that name in .)"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hemiroll::game
