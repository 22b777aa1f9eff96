#include "game/commands/RunCommand.h"

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "engine/record/ContentHash.h"
#include "engine/record/FileNames.h"
#include "engine/script/BotScript.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/ScriptError.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/commands/RunOptions.h"
#include "game/trial/BuiltinBots.h"
#include "game/trial/BotTrial.h"
#include "game/trial/JsonLine.h"
#include "game/trial/TrialRecording.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

namespace {

int badInput(const std::string& message) {
  std::cerr << "hemiroll run: " << message << "\n";
  return kExitUsage;
}

// Letters, digits, '-' and '_' only (TrialMeta's rule for file names).
std::string safeName(const std::string& text) { return record::fileStemOf(text, "-_", "trial"); }

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// DIR/<level>_<bot>_seed<N>, participant "bot", session "run" (RUN.md).
TrialRecordingDef recordingDef(const RunOptions& o) {
  TrialRecordingDef def;
  def.dir = *o.recordDir;
  def.ids = {"bot", "run"};
  def.trialId = safeName(stem(o.levelPath)) + "_" + safeName(stem(o.botPath)) + "_seed" + std::to_string(o.seed);
  def.renameIfTaken = true;
  def.taskName = "hemiroll run";
  def.levelHash = record::fileContentHash(o.levelPath);
  def.seed = o.seed;
  def.sidecarExtra = {{"level_file", o.levelPath}, {"bot_file", o.botPath}, {"realtime", o.realtime ? "true" : "false"}};
  return def;
}

record::Fields resultColumns(const RunOptions& o, const TrialResult& r) {
  record::Fields extra = TrialRecording::scoreFields(r);
  for (auto& field : TrialRecording::measureFields(r)) extra.push_back(std::move(field));
  extra.emplace_back("bot_file", o.botPath);
  extra.emplace_back("ticks", std::to_string(r.ticks));
  return extra;
}

// The CPU the process has used, all its threads [s]: what a trial costs
// whatever else the machine runs (wall_time grows with the machine's load).
double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string resultLine(const RunOptions& o, const std::string& levelName, const TrialResult& r, double cpuTime) {
  JsonLine line;
  line.add("level", o.levelPath).add("level_name", levelName).add("bot", o.botPath);
  line.add("outcome", script::trialOutcomeName(r.outcome)).add("reason", r.reason);
  line.add("time", r.time, 6);  // the tick's time to the microsecond, not the sum's rounding
  if (r.score)
    line.add("score", *r.score);  // a non-finite score is written as null too
  else
    line.addNull("score");
  line.add("medal", script::medalName(r.medal));
  line.add("ticks", r.ticks).add("wall_time", r.wallTime, 6).add("cpu_time", cpuTime, 6);
  return line.str();
}

}  // namespace

int runRunCommand(const std::vector<std::string>& args) {
  const RunOptionsResult parsed = parseRunOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning("hemiroll run: ", parsed, runUsage())) return *exit;
  const RunOptions& options = parsed.options;

  script::LoadedLevel level;
  std::unique_ptr<script::BotPolicy> bot;
  try {
    script::LevelLoadOptions levelOptions;
    levelOptions.seed = options.seed;
    level = script::LevelLoader(levelOptions).loadFile(options.levelPath);
    BuiltinBotOptions builtin;
    builtin.autopilot.budget = options.autopilotBudget;
    builtin.autopilot.plannerThread = options.realtime;
    builtin.human = options.human;
    bot = makeBot(options.botPath, options.seed, builtin);
  } catch (const script::ScriptError& e) {
    return badInput(e.what());
  }

  TrialSettings settings;
  settings.seed = options.seed;
  settings.realtime = options.realtime;
  haptics::parseGuidanceKind(options.guidance, settings.guidance.kind);  // checked by parseRunOptions
  settings.guidance.stiffness = options.guidanceStiffness;
  settings.guidance.damping = options.guidanceDamping.value_or(10.0);
  if (const std::string problem = haptics::guidanceProblem(settings.guidance, botDeviceSpec()); !problem.empty())
    return badInput("--guidance-" + problem);
  std::unique_ptr<TrialRecording> recording;
  TrialResult result;
  double cpuTime = 0.0;  // [s]
  try {
    BotTrial trial(level, *bot, settings);
    if (options.recordDir) {
      recording = std::make_unique<TrialRecording>(recordingDef(options), level.def, trial.rig().loopDef());
      trial.rig().record(recording->tap());
    }
    const double cpuBefore = processCpuSeconds();
    result = trial.run();
    cpuTime = processCpuSeconds() - cpuBefore;
  } catch (const std::invalid_argument& e) {
    // The level asks for something the device cannot do (a coupling stiffer
    // than it renders stably): a bad level, found when the loop is built.
    return badInput(options.levelPath + ": " + e.what());
  } catch (const TrialRecordingError& e) {
    std::cerr << "hemiroll run: " << e.what() << "\n";
    return kExitFailure;
  }
  if (!result.scoreError.empty()) std::cerr << "hemiroll run: " << result.scoreError << "\n";
  if (!result.endCallbackError.empty()) std::cerr << "hemiroll run: " << result.endCallbackError << "\n";
  if (recording) {
    try {
      recording->finish(result, resultColumns(options, result));
    } catch (const TrialRecordingError& e) {
      std::cerr << "hemiroll run: " << e.what() << "\n";
      std::printf("%s\n", resultLine(options, level.def.name, result, cpuTime).c_str());
      return kExitFailure;
    }
  }
  std::printf("%s\n", resultLine(options, level.def.name, result, cpuTime).c_str());
  std::fflush(stdout);
  return result.outcome == script::TrialOutcome::Success ? kExitOk : kExitFailure;
}

}  // namespace hemiroll::game
