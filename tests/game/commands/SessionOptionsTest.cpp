// game/commands/SessionOptions: the flags of `hemiroll session`, checked
// before any file is read.

#include "game/commands/SessionOptions.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;

TEST(SessionOptions, ReadsEveryFlag) {
  const SessionOptionsResult r =
      parseSessionOptions({"p.lua", "--participant", "p01", "--session=2", "--data", "d", "--bot", "b.lua",
                           "--seed", "9223372036854775807", "--levels", "lv"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.protocolPath, "p.lua");
  EXPECT_EQ(r.options.participant, "p01");
  EXPECT_EQ(r.options.session, "2");
  EXPECT_EQ(r.options.dataRoot, "d");
  EXPECT_EQ(r.options.botPath, "b.lua");
  EXPECT_EQ(r.options.seed, 9223372036854775807u);
  EXPECT_EQ(r.options.levelsDir, "lv");
}

TEST(SessionOptions, DefaultsAreSessionOneTheProtocolsSeedAndNoBot) {
  const SessionOptionsResult r = parseSessionOptions({"--participant=x", "p.lua"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.session, "1");
  EXPECT_FALSE(r.options.seed);
  EXPECT_FALSE(r.options.botPath);
  EXPECT_FALSE(r.options.dataRoot);
  EXPECT_EQ(r.options.levelsDir, "");
}

TEST(SessionOptions, AParticipantAtADeviceBehindTheBridge) {
  const SessionOptionsResult r = parseSessionOptions({"p.lua", "--participant", "p01", "--device", "udp", "--port",
                                                      "50002", "--client-timeout", "3", "--device-profile", "omega3"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.device, "udp");
  EXPECT_EQ(r.options.port, 50002);
  EXPECT_EQ(r.options.clientTimeout, 3.0);
  EXPECT_EQ(r.options.deviceProfile, "omega3");
  EXPECT_EQ(parseSessionOptions({"p.lua", "--participant", "p01", "--device", "udp", "--bot", "b.lua"}).error,
            "--device udp and --bot exclude each other: the participant plays");
  EXPECT_EQ(parseSessionOptions({"p.lua", "--participant", "p01", "--device", "mouse"}).error,
            "--device needs bot or udp, not 'mouse'");
}

TEST(SessionOptions, MistakesAreOneSentence) {
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {{"--participant", "x"}, "missing the protocol file"},
      {{"p.lua"}, "missing --participant ID"},
      {{"p.lua", "--participant", "x", "--seed", "-1"}, "--seed needs a whole number"},
      {{"p.lua", "--participant", "x", "--seed", "9223372036854775808"}, "--seed needs a whole number"},
      {{"p.lua", "--participant"}, "--participant needs a value"},
      {{"p.lua", "--participant", "x", "--realtime"}, "unknown flag '--realtime'"},
      {{"p.lua", "q.lua", "--participant", "x"}, "unexpected argument 'q.lua'"},
      {{"p.lua", "--participants", "3"}, "--participants needs --bot"},
      {{"p.lua", "--participants", "0", "--bot", "human"}, "--participants needs a number of participants from 1 to 1000"},
      {{"p.lua", "--participant", "x", "--human-device", "glove"}, "--human-device needs mouse, mouse-hand or haptic, not 'glove'"},
  };
  for (const auto& [args, expected] : cases) EXPECT_THAT(parseSessionOptions(args).error, HasSubstr(expected));
  EXPECT_TRUE(parseSessionOptions({"--help"}).options.help);
  EXPECT_EQ(parseSessionOptions({"--help"}).error, "");
}

TEST(SessionOptions, ACohortNeedsNoParticipantIdAndTakesTheHumanModelsFlags) {
  const SessionOptionsResult r =
      parseSessionOptions({"p.lua", "--participants", "20", "--bot", "human", "--human-device", "haptic"});
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.options.participants, 20);
  EXPECT_EQ(r.options.participant, "sim");  // the cohort's prefix
  EXPECT_EQ(r.options.human.human.device, human::HandDevice::Haptic);
  EXPECT_EQ(parseSessionOptions({"p.lua", "--participant", "x"}).options.participants, 0);
}

}  // namespace
}  // namespace hemiroll::game
