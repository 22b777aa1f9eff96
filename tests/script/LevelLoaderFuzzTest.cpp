// engine/script/LevelLoader under random mutation of every shipped level:
// whatever the text, the loader returns a valid LevelDef or throws one
// ScriptError that starts "file:line: ", and a level that loads can be run
// and scored without escaping errors. Seeded (EngineRandom), so a failure
// repeats; the mutation classes are listed in docs/LEVELS.md ("Fuzzing").

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "engine/task/EngineRandom.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/ScriptError.h"
#include "engine/task/TrialSummaryAccumulator.h"

namespace hemiroll::script {
namespace {

enum class Mutation {
  ByteFlip, Truncate, SwapTokens, DeleteLine, DuplicateLine, ExtremeNumber,
  DeepNesting, StringToOther, InsertStatement, InsertUnknownKey, Count
};

const char* mutationName(Mutation m) {
  static const char* const names[] = {"byte flip", "truncation", "token swap", "deleted line", "duplicated line",
                                      "extreme number", "deep nesting", "string replaced", "inserted statement",
                                      "unknown key"};
  return names[static_cast<int>(m)];
}

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

std::size_t pick(EngineRandom& rng, std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(n) - 1)); }

// Start offsets of the runs of characters for which pred holds.
template <class Pred>
std::vector<std::pair<std::size_t, std::size_t>> runs(const std::string& s, Pred pred) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < s.size();) {
    if (!pred(s[i])) { ++i; continue; }
    std::size_t j = i;
    while (j < s.size() && pred(s[j])) ++j;
    out.emplace_back(i, j - i);
    i = j;
  }
  return out;
}

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

std::string mutate(std::string s, Mutation m, EngineRandom& rng) {
  if (s.empty()) return s;
  switch (m) {
    case Mutation::ByteFlip: {
      for (int n = 1 + static_cast<int>(pick(rng, 4)); n > 0; --n) s[pick(rng, s.size())] = static_cast<char>(rng.integer(0, 255));
      return s;
    }
    case Mutation::Truncate: return s.substr(0, pick(rng, s.size()));
    case Mutation::SwapTokens: {
      auto words = runs(s, isWordChar);
      if (words.size() < 2) return s;
      auto a = words[pick(rng, words.size())], b = words[pick(rng, words.size())];
      if (a.first > b.first) std::swap(a, b);
      if (a.first == b.first) return s;
      const std::string wa = s.substr(a.first, a.second), wb = s.substr(b.first, b.second);
      s.replace(b.first, b.second, wa);
      s.replace(a.first, a.second, wb);
      return s;
    }
    case Mutation::DeleteLine:
    case Mutation::DuplicateLine: {
      auto lines = runs(s, [](char c) { return c != '\n'; });
      if (lines.empty()) return s;
      const auto line = lines[pick(rng, lines.size())];
      if (m == Mutation::DeleteLine) return s.erase(line.first, line.second);
      return s.insert(line.first, s.substr(line.first, line.second) + "\n");
    }
    case Mutation::ExtremeNumber: {
      auto numbers = runs(s, [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; });
      if (numbers.empty()) return s;
      static const char* const values[] = {"1e308", "-1e308", "1e309", "(0/0)", "(1/0)", "(-1/0)", "0", "-0.0",
                                           "-1", "1e-320", "9223372036854775807", "0x7fffffffffffffff", "1e400"};
      const auto at = numbers[pick(rng, numbers.size())];
      return s.replace(at.first, at.second, values[pick(rng, std::size(values))]);
    }
    case Mutation::DeepNesting: {
      const std::size_t depth = 50 + pick(rng, 400);
      auto braces = runs(s, [](char c) { return c == '{'; });
      const std::size_t at = braces.empty() ? 0 : braces[pick(rng, braces.size())].first;
      const bool parens = rng.integer(0, 1) == 1;
      std::string open, close;
      for (std::size_t i = 0; i < depth; ++i) {
        open += parens ? "(" : "{";
        close += parens ? ")" : "}";
      }
      s.insert(at, open + "1" + close + (parens ? "" : ","));
      return s;
    }
    case Mutation::StringToOther: {
      auto strings = runs(s, [](char c) { return c == '"'; });
      if (strings.size() < 2) return s;
      const std::size_t i = pick(rng, strings.size() - 1);
      const std::size_t from = strings[i].first, to = strings[i + 1].first + 1;
      static const char* const values[] = {"42", "{}", "nil", "true", "function() end", "{ {}, {} }", "\"\""};
      return s.replace(from, to - from, values[pick(rng, std::size(values))]);
    }
    case Mutation::InsertStatement: {
      static const char* const statements[] = {"\nwhile true do end\n", "\nerror('boom')\n", "\nlocal t = {} t.x.y = 1\n",
                                               "\nreturn nil\n", "\nio.write('x')\n", "\nos.exit(1)\n",
                                               "\nload('return 1')()\n", "\nrequire('../x')\n",
                                               "\nlocal s = string.rep('x', 1 << 30)\n", "\nsetmetatable({}, {__gc = print})\n"};
      auto lines = runs(s, [](char c) { return c == '\n'; });
      const std::size_t at = lines.empty() ? 0 : lines[pick(rng, lines.size())].first;
      return s.insert(at, statements[pick(rng, std::size(statements))]);
    }
    case Mutation::InsertUnknownKey: {
      auto braces = runs(s, [](char c) { return c == '{'; });
      if (braces.empty()) return s;
      return s.insert(braces[pick(rng, braces.size())].first + 1, " zz_unknown = 1, ");
    }
    case Mutation::Count: break;
  }
  return s;
}

// A loaded level must be a valid one.
void expectValid(const LevelDef& d) {
  EXPECT_FALSE(d.name.empty());
  EXPECT_TRUE(d.params.radius > 0 && std::isfinite(d.params.radius));
  EXPECT_TRUE(d.params.pointMass > 0 && std::isfinite(d.params.pointMass));
  EXPECT_TRUE(d.initial.allFinite());
  EXPECT_TRUE(d.task.timeLimit > 0 && std::isfinite(d.task.timeLimit));
  EXPECT_TRUE(d.callbacks.rate >= 10 && d.callbacks.rate <= 100);
  for (const StageDef& stage : d.task.stages) {
    EXPECT_FALSE(stage.targets.empty());
    EXPECT_TRUE(stage.hold >= 0 && std::isfinite(stage.hold));
    for (const TargetDef& t : stage.targets) EXPECT_TRUE(t.tolerance > 0 && std::isfinite(t.tolerance) && std::isfinite(t.value));
  }
}

TEST(LevelLoaderFuzz, EveryMutationGivesALevelOrAFileLineError) {
  const auto start = std::chrono::steady_clock::now();
  // Small budgets: an endless loop or a memory bomb costs milliseconds, not
  // seconds, and the same code paths run as with the defaults.
  LevelLoadOptions options;
  options.limits.chunkInstructionQuota = 200'000;
  options.limits.callInstructionQuota = 20'000;
  options.limits.memoryLimitBytes = std::size_t{8} << 20;
  const LevelLoader loader(options);
  const std::regex located(R"(^[a-z0-9_]+\.lua:[0-9]+: .+)");

  EngineRandom rng(20261122);
  constexpr int kPerLevel = 500;
  int loaded = 0, refused = 0, levels = 0;
  int perClass[static_cast<int>(Mutation::Count)] = {};
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(HEMIROLL_SOURCE_DIR) / "levels")) {
    if (entry.path().extension() != ".lua") continue;
    ++levels;
    const std::string original = readFile(entry.path());
    const std::string name = entry.path().filename().string();
    for (int i = 0; i < kPerLevel; ++i) {
      const auto m = static_cast<Mutation>(rng.integer(0, static_cast<int>(Mutation::Count) - 1));
      ++perClass[static_cast<int>(m)];
      std::string text = mutate(original, m, rng);
      if (rng.integer(0, 3) == 0) text = mutate(text, static_cast<Mutation>(rng.integer(0, 9)), rng);  // a second one
      try {
        LoadedLevel level = loader.loadSource(text, name);
        ++loaded;
        expectValid(level.def);
        // Run it briefly at rest and score it: errors must come back as reasons.
        TaskJudge judge(level.def.task);
        TrialSummaryAccumulator acc;
        TrialObservation obs;
        for (int tick = 0; tick <= 120 && !judge.finished(); ++tick) {
          obs.time = tick * 0.001;
          JudgeInput in;
          in.time = obs.time;
          judge.judge(in);
          acc.add(in, {}, judge);
          level.script->update(obs, judge);
        }
        const ScoreResult score = level.script->score(acc.summary(judge));
        if (score.score) {
          EXPECT_TRUE(std::isfinite(*score.score));
        }
      } catch (const ScriptError& e) {
        ++refused;
        EXPECT_TRUE(std::regex_match(std::string(e.what()), located))
            << mutationName(m) << " of " << name << " -> " << e.what();
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(levels, 10);
  for (int c = 0; c < static_cast<int>(Mutation::Count); ++c) EXPECT_GT(perClass[c], 0) << mutationName(static_cast<Mutation>(c));
  // Both outcomes occur: the mutations neither all break nor all spare the text.
  EXPECT_GT(loaded, 0);
  EXPECT_GT(refused, 0);
  std::printf("[ fuzz ] %d cases (%d loaded, %d refused with file:line) in %.2f s\n", loaded + refused, loaded, refused,
              seconds);
}

}  // namespace
}  // namespace hemiroll::script
