#include "game/commands/RunCommand.h"

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "engine/record/ContentHash.h"
#include "engine/record/FileNames.h"
#include "engine/haptics/devices/DeviceNames.h"
#include "engine/script/BotScript.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/ScriptError.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/commands/RunOptions.h"
#include "game/trial/BuiltinBots.h"
#include "game/trial/BotTrial.h"
#include "game/trial/DeviceProfiles.h"
#include "game/trial/DeviceTrial.h"
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
TrialRecordingDef recordingDef(const RunOptions& o, const TrialSettings& settings) {
  TrialRecordingDef def;
  def.dir = *o.recordDir;
  def.ids = {"bot", "run"};
  const std::string player = o.device == haptics::kUdpDevice ? std::string(haptics::kUdpDevice) : safeName(stem(o.botPath));
  def.trialId = safeName(stem(o.levelPath)) + "_" + player + "_seed" + std::to_string(o.seed);
  def.renameIfTaken = true;
  def.taskName = "hemiroll run";
  def.levelHash = record::fileContentHash(o.levelPath);
  def.seed = o.seed;
  def.sidecarExtra = {{"level_file", o.levelPath}, {"bot_file", o.botPath}, {"realtime", o.realtime ? "true" : "false"},
                      {"device_profile", o.deviceProfile.value_or("")}};
  def.deviceSpec = settings.device;
  def.deviceName = o.device;
  return def;
}

record::Fields resultColumns(const RunOptions& o, const TrialResult& r, const DeviceTrial* device) {
  record::Fields extra = TrialRecording::scoreFields(r);
  for (auto& field : TrialRecording::measureFields(r)) extra.push_back(std::move(field));
  extra.emplace_back("bot_file", o.botPath);
  extra.emplace_back("device_profile", o.deviceProfile.value_or(""));
  for (auto& field : deviceResultFields(device)) extra.push_back(std::move(field));
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

std::string resultLine(const RunOptions& o, const std::string& levelName, const TrialResult& r, double cpuTime,
                       const DeviceTrial* device = nullptr) {
  JsonLine line;
  line.add("level", o.levelPath).add("level_name", levelName).add("bot", device ? std::string() : o.botPath);
  line.add("outcome", task::trialOutcomeName(r.outcome)).add("reason", r.reason);
  line.add("time", r.time, 6);  // the tick's time to the microsecond, not the sum's rounding
  if (r.score)
    line.add("score", *r.score);  // a non-finite score is written as null too
  else
    line.addNull("score");
  line.add("medal", task::medalName(r.medal));
  line.add("ticks", r.ticks).add("wall_time", r.wallTime, 6).add("cpu_time", cpuTime, 6);
  if (device) {  // a person at a device: how the device fared (RUN.md)
    const haptics::UdpBridgeCounters c = device->counters();
    line.add("device", haptics::kUdpDevice).add("device_profile", o.deviceProfile.value_or("")).add("stop", device->stopWords());
    line.add("packets_received", static_cast<long long>(c.accepted)).add("packets_lost", static_cast<long long>(c.lost));
    line.add("packets_out_of_order", static_cast<long long>(c.outOfOrder)).add("packets_late", static_cast<long long>(c.late));
    line.add("packets_malformed", static_cast<long long>(c.malformed));
  }
  return line.str();
}

// Finishes the recording (if any) and prints the line; the exit code.
int report(const RunOptions& o, const std::string& levelName, TrialRecording* recording, const TrialResult& result,
           double cpuTime, const DeviceTrial* device) {
  if (!result.scoreError.empty()) std::cerr << "hemiroll run: " << result.scoreError << "\n";
  if (!result.endCallbackError.empty()) std::cerr << "hemiroll run: " << result.endCallbackError << "\n";
  const std::string line = resultLine(o, levelName, result, cpuTime, device);
  if (recording) {
    try {
      std::optional<haptics::LoopTimingSummary> timing;
      record::Fields outcome;
      if (device) {
        timing = device->timing();
        outcome = deviceOutcomeFields(*device);
      }
      recording->finish(result, resultColumns(o, result, device), timing, outcome);
    } catch (const TrialRecordingError& e) {
      std::cerr << "hemiroll run: " << e.what() << "\n";
      std::printf("%s\n", line.c_str());
      return kExitFailure;
    }
  }
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
  return result.outcome == task::TrialOutcome::Success ? kExitOk : kExitFailure;
}

// `--realtime --device udp`: a person at a device behind the bridge, on the
// trial rig the window uses (DeviceTrial).
int runAtDevice(const RunOptions& o, script::LoadedLevel& level, const TrialSettings& settings,
                const std::optional<task::DeviceProfileDef>& profile) {
  DeviceTrialDef def;
  def.bridge.port = static_cast<std::uint16_t>(o.port);
  if (profile) {
    def.bridge.spec = settings.device;
    def.safety = settings.safety;
  }
  def.clientTimeout = o.clientTimeout;
  std::unique_ptr<TrialRecording> recording;
  TrialResult result;
  double cpuTime = 0.0;
  try {
    DeviceTrial trial(level, def);
    if (o.recordDir) {
      TrialSettings recorded = settings;
      recorded.device = def.bridge.spec;
      recording = std::make_unique<TrialRecording>(recordingDef(o, recorded), level.def, trial.rig().loopDef());
      trial.rig().record(recording->tap());
    }
    const double cpuBefore = processCpuSeconds();
    result = trial.run();
    cpuTime = processCpuSeconds() - cpuBefore;
    return report(o, level.def.name, recording.get(), result, cpuTime, &trial);
  } catch (const std::invalid_argument& e) {
    return badInput(o.levelPath + ": " + e.what());
  } catch (const std::runtime_error& e) {  // the bridge could not open, the recording could not start
    std::cerr << "hemiroll run: " << e.what() << "\n";
    return kExitFailure;
  }
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
    if (options.device == "bot") bot = makeBot(options.botPath, options.seed, builtin);
  } catch (const script::ScriptError& e) {
    return badInput(e.what());
  }

  TrialSettings settings;
  settings.seed = options.seed;
  settings.realtime = options.realtime;
  haptics::parseGuidanceKind(options.guidance, settings.guidance.kind);  // checked by parseRunOptions
  settings.guidance.stiffness = options.guidanceStiffness;
  settings.guidance.damping = options.guidanceDamping.value_or(10.0);
  std::optional<task::DeviceProfileDef> profile;
  if (options.deviceProfile) {
    try {
      profile = loadDeviceProfile(*options.deviceProfile);
    } catch (const script::ScriptError& e) {
      return badInput(e.what());
    }
    if (const std::string refusal = couplingRefusal(*profile, level.def.coupling, options.levelPath); !refusal.empty())
      return badInput(refusal);
    settings.device = deviceSpecOf(*profile);
    settings.safety = safetyOf(*profile);
  }
  if (options.device == haptics::kUdpDevice) return runAtDevice(options, level, settings, profile);
  if (const std::string problem = haptics::guidanceProblem(settings.guidance, settings.device); !problem.empty())
    return badInput("--guidance-" + problem);
  std::unique_ptr<TrialRecording> recording;
  TrialResult result;
  double cpuTime = 0.0;  // [s]
  try {
    BotTrial trial(level, *bot, settings);
    if (options.recordDir) {
      recording = std::make_unique<TrialRecording>(recordingDef(options, settings), level.def, trial.rig().loopDef());
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
  return report(options, level.def.name, recording.get(), result, cpuTime, nullptr);
}

}  // namespace hemiroll::game
