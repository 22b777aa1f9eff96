// engine/script/ProtocolLoader: protocol files into ProtocolDef, level files
// found beside the protocol or in the levels folder, and one "file:line:
// path: what" message per mistake.

#include "engine/script/ProtocolLoader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kLevels = std::string(HEMIROLL_SOURCE_DIR) + "/levels";

// A folder with a protocol's own level beside it; the shipped levels are the
// levels folder.
class ProtocolLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_.write("mine.lua", "return { name = 'mine' }"); }

  ProtocolDef load(const std::string& source) const {
    ProtocolLoadOptions options;
    options.levelsDir = kLevels;
    return ProtocolLoader(options).loadSource(source, "p.lua", dir_.path().string());
  }
  std::string errorOf(const std::string& source) const {
    return test::messageOf<ScriptError>([&] { load(source); });
  }

  test::TempDirectory dir_;
};

TEST_F(ProtocolLoaderTest, MinimalProtocolHasTheDefaults) {
  const ProtocolDef def = load("return { experiment = 'e1', blocks = { { level = 'mine.lua' } } }");
  EXPECT_EQ(def.experiment, "e1");
  EXPECT_EQ(def.seed, 0u);
  EXPECT_EQ(def.version, "1");
  ASSERT_EQ(def.blocks.size(), 1u);
  const BlockDef& b = def.blocks[0];
  EXPECT_EQ(b.name, "block 1");
  EXPECT_EQ(b.repetitions, 1);
  EXPECT_FALSE(b.randomise);
  EXPECT_FALSE(b.breakAfter);
  ASSERT_EQ(b.conditions.size(), 1u);
  EXPECT_EQ(b.conditions[0].level, "mine.lua");
  EXPECT_EQ(b.conditions[0].levelPath, (dir_.path() / "mine.lua").lexically_normal().string());
  EXPECT_TRUE(b.conditions[0].overrides.empty());
  EXPECT_EQ(b.conditions[0].label, "mine");  // the level file's stem
}

TEST_F(ProtocolLoaderTest, AStudyNamesItsDevice) {
  EXPECT_EQ(load("return { experiment = 'e1', blocks = { { level = 'mine.lua' } } }").deviceProfile, "");
  EXPECT_EQ(load("return { experiment = 'e1', device_profile = 'touch', blocks = { { level = 'mine.lua' } } }")
                .deviceProfile,
            "touch");
  EXPECT_THAT(errorOf("return { experiment = 'e1', device_profile = '', blocks = { { level = 'mine.lua' } } }"),
              ::testing::HasSubstr("device_profile: must name a device profile"));
  EXPECT_THAT(errorOf("return { experiment = 'e1', device_profile = 3, blocks = { { level = 'mine.lua' } } }"),
              ::testing::HasSubstr("device_profile"));
}

TEST_F(ProtocolLoaderTest, ReadsEveryFieldAndMergesBlockValuesIntoConditions) {
  const ProtocolDef def = load(R"(
    return {
      experiment = "exp-2", description = "d", version = "3", seed = 12345678901,
      blocks = {
        { name = "a", instructions = "go", label = "only", level = "mine.lua", method = "M1", kr = 100, kv = 5,
          time_limit = 30, repetitions = 4, break_after = { message = "rest", min_duration = 90, stop = true } },
        { level = "tutorial_01_tilt_and_return.lua", method = "M3", kr = 250, alpha = 3, randomise = true,
          conditions = { { label = "x", alpha = 1.5 }, { method = "visual", level = "mine.lua", time_limit = 1e3 } } },
      },
    })");
  EXPECT_EQ(def.description, "d");
  EXPECT_EQ(def.version, "3");
  EXPECT_EQ(def.seed, 12345678901u);
  const BlockDef& a = def.blocks[0];
  EXPECT_EQ(a.name, "a");
  EXPECT_EQ(a.instructions, "go");
  EXPECT_EQ(a.repetitions, 4);
  ASSERT_TRUE(a.breakAfter);
  EXPECT_EQ(a.breakAfter->message, "rest");
  EXPECT_EQ(a.breakAfter->minDuration, 90.0);
  EXPECT_TRUE(a.breakAfter->stop);
  EXPECT_EQ(a.conditions[0].label, "only");
  EXPECT_EQ(*a.conditions[0].overrides.method, "M1");
  EXPECT_EQ(*a.conditions[0].overrides.stiffness, 100.0);
  EXPECT_EQ(*a.conditions[0].overrides.damping, 5.0);
  EXPECT_FALSE(a.conditions[0].overrides.alpha);
  EXPECT_EQ(*a.conditions[0].overrides.timeLimit, 30.0);

  const BlockDef& b = def.blocks[1];
  EXPECT_EQ(b.name, "block 2");
  EXPECT_TRUE(b.randomise);
  ASSERT_EQ(b.conditions.size(), 2u);
  // The block's level and values, the condition's own win.
  EXPECT_EQ(b.conditions[0].levelPath, std::filesystem::path(kLevels + "/tutorial_01_tilt_and_return.lua")
                                           .lexically_normal().string());
  EXPECT_EQ(b.conditions[0].label, "x");
  EXPECT_EQ(*b.conditions[0].overrides.method, "M3");
  EXPECT_EQ(*b.conditions[0].overrides.alpha, 1.5);
  EXPECT_EQ(*b.conditions[0].overrides.stiffness, 250.0);
  EXPECT_EQ(b.conditions[1].level, "mine.lua");
  EXPECT_EQ(*b.conditions[1].overrides.method, "visual");
  EXPECT_EQ(*b.conditions[1].overrides.alpha, 3.0);
  EXPECT_EQ(*b.conditions[1].overrides.timeLimit, 1000.0);
  EXPECT_EQ(b.conditions[1].label, "visual kr 250 alpha 3 time limit 1000 s");  // built from the overrides
}

TEST_F(ProtocolLoaderTest, ALevelBesideTheProtocolWinsOverTheLevelsFolder) {
  dir_.write("tutorial_01_tilt_and_return.lua", "return { name = 'shadow' }");
  const ProtocolDef def = load("return { experiment = 'e', blocks = { { level = 'tutorial_01_tilt_and_return.lua' } } }");
  EXPECT_EQ(def.blocks[0].conditions[0].levelPath,
            (dir_.path() / "tutorial_01_tilt_and_return.lua").lexically_normal().string());
}

TEST_F(ProtocolLoaderTest, LoadFileFindsTheLevelsFolderAboveTheProtocol) {
  std::filesystem::create_directories(dir_.path() / "levels" / "protocols");
  dir_.write("levels/target.lua", "return { name = 't' }");
  const std::string path =
      dir_.write("levels/protocols/p.lua", "return { experiment = 'e', blocks = { { level = 'target.lua' } } }");
  const ProtocolLoader loader;
  EXPECT_EQ(loader.levelsDirFor(path), (dir_.path() / "levels").string());
  EXPECT_EQ(loader.loadFile(path).blocks[0].conditions[0].levelPath, (dir_.path() / "levels/target.lua").string());
}

TEST(ProtocolLoaderFiles, AMissingProtocolFileIsOneSentenceWithLineOne) {
  try {
    ProtocolLoader().loadFile("/nonexistent/p.lua");
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/p.lua:1: no such file");
  }
}

TEST(ProtocolLoaderFiles, TheShippedProtocolsLoad) {
  for (const char* name : {"paper_two_days.lua", "tutorial_demo.lua", "paper_guidance.lua"}) {
    const std::string path = kLevels + "/protocols/" + name;
    ProtocolDef def;
    ASSERT_NO_THROW(def = ProtocolLoader().loadFile(path)) << path;
    EXPECT_FALSE(def.blocks.empty()) << path;
    for (const BlockDef& b : def.blocks)
      for (const ConditionDef& c : b.conditions) EXPECT_TRUE(std::filesystem::exists(c.levelPath)) << c.levelPath;
  }
}

// The paper's two days (Sec. 4): what the protocol must say to be the paper's.
TEST(ProtocolLoaderFiles, ThePapersProtocolHasThePapersConditions) {
  const ProtocolDef def = ProtocolLoader().loadFile(kLevels + "/protocols/paper_two_days.lua");
  ASSERT_EQ(def.blocks.size(), 3u);
  const BlockDef& assessment = def.blocks[1];
  std::vector<std::string> labels;
  for (const ConditionDef& c : assessment.conditions) {
    labels.push_back(c.label);
    EXPECT_EQ(*c.overrides.stiffness, 250.0);  // Sec. 4.1, paras. 2 and 3
    EXPECT_EQ(*c.overrides.damping, 10.0);
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"M1", "M2", "M3 alpha 1", "M3 alpha 1.5", "M3 alpha 2", "M3 alpha 2.5",
                                              "M3 alpha 3", "M3 alpha 4", "visual only"}));
  ASSERT_TRUE(assessment.breakAfter);
  EXPECT_TRUE(assessment.breakAfter->stop);  // the end of day 1
  const BlockDef& day2 = def.blocks[2];
  EXPECT_EQ(day2.repetitions, 15);  // Sec. 4.2
  ASSERT_EQ(day2.conditions.size(), 1u);
  EXPECT_EQ(*day2.conditions[0].overrides.method, "M3");
  EXPECT_EQ(*day2.conditions[0].overrides.alpha, 2.0);
  EXPECT_EQ(*day2.conditions[0].overrides.timeLimit, 240.0);  // Sec. 4, para. 4
}

// docs/PROTOCOLS.md's complete example is a protocol that loads, with every key.
TEST(ProtocolLoaderFiles, TheDocumentedExampleLoads) {
  std::ifstream doc(std::string(HEMIROLL_SOURCE_DIR) + "/docs/PROTOCOLS.md");
  std::string line, example;
  bool inside = false;
  while (std::getline(doc, line)) {
    if (!inside && line == "```lua") inside = true;
    else if (inside && line == "```") break;
    else if (inside) example += line + "\n";
  }
  ASSERT_FALSE(example.empty());
  ProtocolLoadOptions options;
  options.levelsDir = kLevels;
  const ProtocolDef def = ProtocolLoader(options).loadSource(example, "example.lua", kLevels + "/protocols");
  EXPECT_EQ(def.experiment, "example");
  EXPECT_EQ(def.seed, 42u);
  ASSERT_EQ(def.blocks.size(), 3u);
  EXPECT_EQ(def.blocks[0].repetitions, 2);
  EXPECT_EQ(def.blocks[0].conditions[0].label, "warm-up");
  ASSERT_EQ(def.blocks[1].conditions.size(), 4u);
  EXPECT_EQ(def.blocks[1].repetitions, 3);
  EXPECT_TRUE(def.blocks[1].randomise);
  EXPECT_EQ(*def.blocks[1].conditions[3].overrides.method, "M2");
  EXPECT_EQ(*def.blocks[1].conditions[3].overrides.stiffness, 250.0);
  ASSERT_TRUE(def.blocks[1].breakAfter);
  EXPECT_TRUE(def.blocks[1].breakAfter->stop);
  EXPECT_EQ(*def.blocks[2].conditions[0].overrides.timeLimit, 30.0);
}

TEST_F(ProtocolLoaderTest, GuidanceIsReadMergedAndFadedPerTrial) {
  const ProtocolDef def = load(
      "return { experiment = 'g', blocks = {\n"
      " { level = 'mine.lua', repetitions = 5,\n"
      "   guidance = { kind = 'autopilot', stiffness = 300, damping = 10, max_error = 0.01,\n"
      "                fade = { from = 1, to = 0, over_trials = 3 } },\n"
      "   conditions = { {}, { guidance = { kind = 'error_augmentation', gain = 40 } }, { guidance = { kind = 'none' } } } } } }");
  const std::vector<ConditionDef>& c = def.blocks.at(0).conditions;
  ASSERT_EQ(c.size(), 3u);
  ASSERT_TRUE(c[0].overrides.guidance);
  const GuidanceSpec& guided = *c[0].overrides.guidance;
  EXPECT_EQ(guided.kind, "autopilot");
  EXPECT_EQ(guided.stiffness, 300.0);
  EXPECT_EQ(guided.damping, 10.0);
  EXPECT_EQ(guided.maxError, 0.01);
  EXPECT_EQ(c[0].label, "guided");
  // The fade: 1 at the block's first trial, linear to 0 at the third, then held.
  EXPECT_EQ(guided.fadeAt(1), 1.0);
  EXPECT_EQ(guided.fadeAt(2), 0.5);
  EXPECT_EQ(guided.fadeAt(3), 0.0);
  EXPECT_EQ(guided.fadeAt(5), 0.0);
  // A condition's own guidance replaces the block's whole (no field merge).
  ASSERT_TRUE(c[1].overrides.guidance);
  EXPECT_EQ(c[1].overrides.guidance->kind, "error_augmentation");
  EXPECT_EQ(c[1].overrides.guidance->stiffness, 40.0);
  EXPECT_EQ(c[1].overrides.guidance->damping, 0.0);
  EXPECT_EQ(c[1].overrides.guidance->fadeAt(1), 1.0);  // no fade given: full every trial
  EXPECT_EQ(c[1].label, "error augmented");
  EXPECT_EQ(c[2].overrides.guidance->kind, "none");
}

struct ErrorCase {
  const char* source;
  const char* expected;  // the complete "p.lua:LINE: path: what" start
};

class ProtocolLoaderErrors : public ProtocolLoaderTest, public ::testing::WithParamInterface<ErrorCase> {};

TEST_P(ProtocolLoaderErrors, NameFileLineAndWhat) {
  EXPECT_THAT(errorOf(GetParam().source), StartsWith(GetParam().expected)) << GetParam().source;
}

// One case per class of mistake; the line is where the field is written.
INSTANTIATE_TEST_SUITE_P(
    Classes, ProtocolLoaderErrors,
    ::testing::Values(
        ErrorCase{"return {\n experiment = 'e',\n blokcs = {} }", "p.lua:3: blokcs: unknown key 'blokcs' (did you mean 'blocks'?)"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   repetitons = 2 } } }",
                  "p.lua:3: blocks[1].repetitons: unknown key 'repetitons' (did you mean 'repetitions'?)"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', conditions = {\n  { alpah = 2 } } } } }",
                  "p.lua:3: blocks[1].conditions[1].alpah: unknown key 'alpah' (did you mean 'alpha'?)"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   break_after = { mesage = 'x' } } } }",
                  "p.lua:3: blocks[1].break_after.mesage: unknown key 'mesage' (did you mean 'message'?)"},
        ErrorCase{"return {\n blocks = { { level = 'mine.lua' } } }", "p.lua:1: experiment: missing"},
        ErrorCase{"return {\n experiment = 'a/b', blocks = { { level = 'mine.lua' } } }",
                  "p.lua:2: experiment: 'a/b' is not a folder name"},
        ErrorCase{"return {\n experiment = 7, blocks = { { level = 'mine.lua' } } }", "p.lua:2: experiment: expected a string, got number"},
        ErrorCase{"return {\n experiment = 'e' }", "p.lua:1: blocks: missing"},
        ErrorCase{"return { experiment = 'e',\n blocks = {} }", "p.lua:2: blocks: empty"},
        ErrorCase{"return { experiment = 'e',\n blocks = { a = { level = 'mine.lua' } } }", "p.lua:2: blocks: expected a list of blocks"},
        ErrorCase{"return { experiment = 'e', blocks = {\n 'mine.lua' } }", "p.lua:2: blocks[1]: expected a block table"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { name = 'no level' } } }", "p.lua:2: blocks[1].level: missing"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua' },\n { level = 'gone.lua' } } }",
                  "p.lua:3: blocks[2].level: no level file 'gone.lua' (looked in "},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', conditions = {\n  {},\n  { level = 'x.lua' } } } } }",
                  "p.lua:4: blocks[1].conditions[2].level: no level file 'x.lua'"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { conditions = {\n  { alpha = 2 } } } } }",
                  "p.lua:3: blocks[1].conditions[1].level: missing; give the level file in the condition or in its block"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 42 } } }", "p.lua:2: blocks[1].level: expected a string, got number"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   method = 'M4' } } }",
                  "p.lua:3: blocks[1].method: unknown method 'M4' (did you mean 'M1'?)"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   method = 'haptic' } } }",
                  "p.lua:3: blocks[1].method: unknown method 'haptic' (expected \"M1\", \"M2\", \"M3\" or \"visual\")"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', conditions = {\n  { alpha = 0 } } } } }",
                  "p.lua:3: blocks[1].conditions[1].alpha: must be a positive number"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   alpha = -1 } } }",
                  "p.lua:3: blocks[1].alpha: must be a positive number"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   kr = -250 } } }",
                  "p.lua:3: blocks[1].kr: must be >= 0 (stiffness, N/m)"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   kv = '10' } } }",
                  "p.lua:3: blocks[1].kv: expected a number, got string"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   time_limit = 0 } } }",
                  "p.lua:3: blocks[1].time_limit: must be a positive number (s)"},
        // A level's bounds hold in a protocol too (issue 33): a time limit of a
        // day at most, gains within 1e6 N/m, 1e4 N s/m, an alpha of 100.
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   time_limit = 1e16 } } }",
                  "p.lua:3: blocks[1].time_limit: must be at most 86400 s (a day), as a level's"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', conditions = {\n  { kr = 1e300 } } } } }",
                  "p.lua:3: blocks[1].conditions[1].kr: (stiffness) must be at most 1e6 N/m"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   kv = 1e5 } } }",
                  "p.lua:3: blocks[1].kv: (damping) must be at most 1e4 N s/m"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   alpha = 1e3 } } }",
                  "p.lua:3: blocks[1].alpha: (normal/in-face gain ratio) must be at most 100"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   guidance = { kind = 'autopilot', stiffness = 1e300 } } } }",
                  "p.lua:3: blocks[1].guidance.stiffness: must be at most 1e6 N/m"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   guidance = { kind = 'error_augmentation', gain = 5, damping = 1e9 } } } }",
                  "p.lua:3: blocks[1].guidance.damping: must be at most 1e4 N s/m"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   guidance = { kind = 'autopilot', stiffness = 1, max_error = 5 } } } }",
                  "p.lua:3: blocks[1].guidance.max_error: must be at most 1 m"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   repetitions = 0 } } }",
                  "p.lua:3: blocks[1].repetitions: expected a whole number from 1 to 10000"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   repetitions = 2.5 } } }",
                  "p.lua:3: blocks[1].repetitions: expected a whole number from 1 to 10000"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   randomise = 'yes' } } }",
                  "p.lua:3: blocks[1].randomise: expected true or false, got string"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', conditions = {} } } }",
                  "p.lua:2: blocks[1].conditions: empty"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', label = 'x',\n   conditions = { {} } } } }",
                  "p.lua:2: blocks[1].label: a block with conditions has no label of its own"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   break_after = { min_duration = -1 } },\n { level = 'mine.lua' } } }",
                  "p.lua:3: blocks[1].break_after.min_duration: must be >= 0 (s)"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   break_after = { message = 'x' } } } }",
                  "p.lua:3: blocks[1].break_after: the last block has no block after it"},
        ErrorCase{"return { experiment = 'e',\n seed = -1, blocks = { { level = 'mine.lua' } } }",
                  "p.lua:2: seed: expected a whole number from 0 to 9223372036854775807, got number"},
        ErrorCase{"return { experiment = 'e',\n seed = 0.5, blocks = { { level = 'mine.lua' } } }", "p.lua:2: seed: expected a whole number"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', repetitions = 10000, conditions = {\n {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {} } } } }",
                  "p.lua:2: blocks[1].repetitions: the plan would exceed 10000 trials"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   guidance = { kind = 'autopilt', stiffness = 300 } } } }",
                  "p.lua:3: blocks[1].guidance.kind: unknown guidance kind 'autopilt' (did you mean 'autopilot'?)"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   guidance = { kind = 'autopilot', stifness = 300 } } } }",
                  "p.lua:3: blocks[1].guidance.stifness: unknown key 'stifness' (did you mean 'stiffness'?)"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   guidance = { kind = 'autopilot' } } } }",
                  "p.lua:3: blocks[1].guidance.stiffness: missing; the guidance spring [N/m]"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua',\n   guidance = { kind = 'error_augmentation', stiffness = 50 } } } }",
                  "p.lua:3: blocks[1].guidance.stiffness: not a key of error_augmentation guidance (its spring is 'gain')"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', guidance = { kind = 'autopilot', stiffness = 300,\n   fade = { from = 1, to = 1.5 } } } } }",
                  "p.lua:3: blocks[1].guidance.fade.to: must be in [0, 1]"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', guidance = { kind = 'autopilot', stiffness = 300,\n   fade = { over_trials = 0 } } } } }",
                  "p.lua:3: blocks[1].guidance.fade.over_trials: expected a whole number from 1 to 10000"},
        ErrorCase{"return { experiment = 'e', blocks = {\n { level = 'mine.lua', guidance = { kind = 'autopilot',\n   stiffness = -1 } } } }",
                  "p.lua:3: blocks[1].guidance.stiffness: must be >= 0 (N/m)"},
        ErrorCase{"return 'protocol'", "p.lua:1: the protocol must return a table, got string"},
        ErrorCase{"return {\n experiment = 'e',\n", "p.lua:3: unexpected symbol near <eof>"},
        ErrorCase{"local x = io.open('f')\nreturn {}", "p.lua:1: attempt to index a nil value (global 'io')"},
        ErrorCase{"while true do end", "p.lua:1: "}));


TEST_F(ProtocolLoaderTest, ReadsGroupsTheirChangesAndTheCounterbalancedBlocks) {
  dir_.write("participants.tsv", "participant_id\tgroup\n");
  const ProtocolDef def = load(R"(
    return {
      experiment = "g", participants = "participants.tsv", assignment = "participants_file",
      counterbalance = { "c", "a" },
      groups = {
        { name = "guided", description = "pulled", changes = { { block = "b", guidance = { kind = "autopilot", stiffness = 300 } } } },
        { name = "control" },
      },
      blocks = { { name = "a", level = "mine.lua" }, { name = "b", level = "mine.lua" }, { name = "c", level = "mine.lua" } },
    })");
  ASSERT_EQ(def.groups.size(), 2u);
  EXPECT_EQ(def.groups[0].name, "guided");
  EXPECT_EQ(def.groups[0].description, "pulled");
  ASSERT_EQ(def.groups[0].changes.size(), 1u);
  EXPECT_EQ(def.groups[0].changes[0].block, 1);
  ASSERT_TRUE(def.groups[0].changes[0].overrides.guidance);
  EXPECT_EQ(def.groups[0].changes[0].overrides.guidance->stiffness, 300.0);
  EXPECT_TRUE(def.groups[1].changes.empty());
  EXPECT_EQ(def.counterbalanced, (std::vector<int>{0, 2}));
  EXPECT_EQ(def.assignment, Assignment::ParticipantsFile);
  EXPECT_EQ(def.participantsFile, (dir_.path() / "participants.tsv").lexically_normal().string());
  EXPECT_EQ(def.orderCount(), 2);
}

// A key far from every name lists the keys the table takes: a block's, a
// condition's and a group change's own keys with every trial override key
// (one list in the loader), in the same order everywhere.
TEST_F(ProtocolLoaderTest, UnknownKeysListTheTablesKeysWithTheOverrides) {
  EXPECT_EQ(errorOf("return { experiment = 'e', blocks = { { level = 'mine.lua', zzzzzz = 1 } } }"),
            "p.lua:1: blocks[1].zzzzzz: unknown key 'zzzzzz' (expected one of: name, instructions, label, level, "
            "conditions, method, kr, kv, alpha, time_limit, guidance, repetitions, randomise, break_after)");
  EXPECT_EQ(errorOf("return { experiment = 'e', blocks = { { level = 'mine.lua', conditions = { { zzzzzz = 1 } } } } }"),
            "p.lua:1: blocks[1].conditions[1].zzzzzz: unknown key 'zzzzzz' (expected one of: label, level, method, kr, "
            "kv, alpha, time_limit, guidance)");
  EXPECT_EQ(errorOf("return { experiment = 'g', groups = { { name = 'x', changes = { { block = 'a', zzzzzz = 1 } } } },"
                    " blocks = { { name = 'a', level = 'mine.lua' } } }"),
            "p.lua:1: groups[1].changes[1].zzzzzz: unknown key 'zzzzzz' (expected one of: block, method, kr, kv, alpha, "
            "time_limit, guidance)");
}

TEST_F(ProtocolLoaderTest, GroupAndCounterbalanceMistakesAreNamed) {
  const std::string blocks = " blocks = { { name = 'a', level = 'mine.lua' }, { name = 'b', level = 'mine.lua' } } }";
  EXPECT_EQ(errorOf("return { experiment = 'g', groups = { { name = 'x', changes = { { block = 'c', kr = 1 } } } }," + blocks),
            "p.lua:1: groups[1].changes[1].block: no block named 'c' (the blocks: 'a', 'b')");
  EXPECT_EQ(errorOf("return { experiment = 'g', groups = { { name = 'x' }, { name = 'x' } }," + blocks),
            "p.lua:1: groups[2].name: 'x' names two groups");
  EXPECT_EQ(errorOf("return { experiment = 'g', groups = { { name = 'x', changes = { { block = 'a' } } } }," + blocks),
            "p.lua:1: groups[1].changes[1]: changes nothing; give method, kr, kv, alpha, time_limit or guidance");
  EXPECT_EQ(errorOf("return { experiment = 'g', counterbalance = { 'a' }," + blocks),
            "p.lua:1: counterbalance: expected a list of at least two block names { \"a\", \"b\" }");
  EXPECT_EQ(errorOf("return { experiment = 'g', counterbalance = { 'a', 'a' }," + blocks),
            "p.lua:1: counterbalance[2]: 'a' is listed twice");
  EXPECT_EQ(errorOf("return { experiment = 'g', assignment = 'random'," + blocks),
            "p.lua:1: assignment: unknown assignment 'random' (expected \"balanced\" or \"participants_file\")");
  EXPECT_EQ(errorOf("return { experiment = 'g', assignment = 'participants_file'," + blocks),
            "p.lua:1: assignment: \"participants_file\" needs the participants file: participants = \"participants.tsv\"");
  EXPECT_EQ(errorOf("return { experiment = 'g', participants = 'nobody.tsv'," + blocks),
            "p.lua:1: participants: no participants file 'nobody.tsv' (looked in " + dir_.path().string() + ")");
  EXPECT_THAT(errorOf("return { experiment = 'g', grups = {}," + blocks), HasSubstr("did you mean 'groups'?"));
  // Names that would quietly mean the first of two.
  EXPECT_EQ(errorOf("return { experiment = 'g', groups = { { name = 'Stiff' }, { name = 'stiff' } }," + blocks),
            "p.lua:1: groups[2].name: 'stiff' and 'Stiff' differ only in case; name groups apart");
  EXPECT_EQ(errorOf("return { experiment = 'g', groups = { { name = 'x', changes = { { block = 'a', kr = 100 },"
                    " { block = 'a', kr = 200 } } } }," + blocks),
            "p.lua:1: groups[1].changes[2].block: 'a' is changed twice in group 'x'; put everything the group changes "
            "in that block into one change");
  EXPECT_EQ(errorOf("return { experiment = 'g', counterbalance = { 'a', 'b' }, blocks = { { name = 'a', level = "
                    "'mine.lua' }, { name = 'b', level = 'mine.lua' }, { name = 'a', level = 'mine.lua' } } }"),
            "p.lua:1: blocks[3].name: 'a' names blocks 1 and 3; groups and counterbalance name blocks, so each needs "
            "its own");
}

}  // namespace
}  // namespace hemiroll::script
