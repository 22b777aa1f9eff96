#include "game/commands/RunCommand.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "engine/script/BotScript.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/ScriptError.h"
#include "game/commands/ExitCode.h"
#include "game/commands/RunOptions.h"
#include "game/play/HeadlessTrial.h"
#include "game/play/JsonLine.h"
#include "game/play/TrialRecording.h"

namespace hemiroll::game {

namespace {

int badInput(const std::string& message) {
  std::cerr << "hemiroll run: " << message << "\n";
  return kExitUsage;
}

std::string resultLine(const RunOptions& o, const TrialResult& r) {
  JsonLine line;
  line.add("level", o.levelPath).add("bot", o.botPath);
  line.add("outcome", script::trialOutcomeName(r.outcome)).add("reason", r.reason);
  line.add("time", r.time);
  if (r.score)
    line.add("score", *r.score);  // a non-finite score is written as null too
  else
    line.addNull("score");
  line.add("medal", script::medalName(r.medal));
  line.add("ticks", r.ticks).add("wall_time", r.wallTime);
  return line.str();
}

}  // namespace

int runRunCommand(const std::vector<std::string>& args) {
  const RunOptionsResult parsed = parseRunOptions(args);
  if (!parsed.error.empty()) {
    std::cerr << "hemiroll run: " << parsed.error << "\n\n" << runUsage();
    return kExitUsage;
  }
  const RunOptions& options = parsed.options;
  if (options.help) {
    std::cout << runUsage();
    return kExitOk;
  }

  script::LoadedLevel level;
  std::unique_ptr<script::BotScript> bot;
  try {
    script::LevelLoadOptions levelOptions;
    levelOptions.seed = options.seed;
    level = script::LevelLoader(levelOptions).loadFile(options.levelPath);
    script::BotLoadOptions botOptions;
    botOptions.seed = options.seed;
    bot = std::make_unique<script::BotScript>(options.botPath, botOptions);
  } catch (const script::ScriptError& e) {
    return badInput(e.what());
  }

  TrialSettings settings;
  settings.seed = options.seed;
  settings.realtime = options.realtime;
  std::unique_ptr<TrialRecording> recording;
  TrialResult result;
  try {
    if (options.recordDir) recording = std::make_unique<TrialRecording>(*options.recordDir, level.def, options, settings);
    result = HeadlessTrial(level, *bot, settings).run();
  } catch (const std::invalid_argument& e) {
    // The level asks for something the device cannot do (a coupling stiffer
    // than it renders stably): a bad level, found when the loop is built.
    return badInput(options.levelPath + ": " + e.what());
  } catch (const TrialRecordingError& e) {
    std::cerr << "hemiroll run: " << e.what() << "\n";
    return kExitFailure;
  }
  if (!result.scoreError.empty()) std::cerr << "hemiroll run: " << result.scoreError << "\n";
  if (recording) {
    try {
      recording->finish(result);
    } catch (const TrialRecordingError& e) {
      std::cerr << "hemiroll run: " << e.what() << "\n";
      std::printf("%s\n", resultLine(options, result).c_str());
      return kExitFailure;
    }
  }
  std::printf("%s\n", resultLine(options, result).c_str());
  std::fflush(stdout);
  return result.outcome == script::TrialOutcome::Success ? kExitOk : kExitFailure;
}

}  // namespace hemiroll::game
