#include "game/commands/CheckCommand.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <optional>
#include <regex>

#include "engine/autopilot/Reachability.h"
#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/haptics/Guidance.h"
#include "engine/haptics/ServoLoop.h"
#include "engine/physics/StateKinematics.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/ProtocolLoader.h"
#include "engine/task/ProtocolPlan.h"
#include "engine/script/ScenarioLoader.h"
#include "engine/script/ScriptError.h"
#include "engine/script/SweepLoader.h"
#include "game/cli/ArgumentReader.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/research/session/ParticipantsFile.h"
#include "game/research/session/ResearchSession.h"
#include "game/trial/DeviceProfiles.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

namespace {

constexpr const char* kPrefix = "hemiroll check: ";

struct CheckOptions {
  std::vector<std::string> files;
  std::optional<CheckedKind> as;
  std::string levelsDir;  // protocols: where levels are looked for, as `session --levels`
  bool help = false;
};

struct CheckOptionsResult {
  CheckOptions options;
  std::string error;
};

const char* kindName(CheckedKind kind) {
  switch (kind) {
    case CheckedKind::Level: return "level";
    case CheckedKind::Protocol: return "protocol";
    case CheckedKind::Scenario: return "scenario";
    case CheckedKind::Sweep: return "sweep spec";
  }
  return "?";
}

std::string checkUsage() {
  return "usage: hemiroll check FILE... [--as level|protocol|scenario|sweep] [--levels DIR]\n"
         "\n"
         "Loads each file as the command that uses it would (play/run, session, sim,\n"
         "sweep) and reports every problem found without playing it: a load error\n"
         "with its file and line; for a level also a coupling the device cannot\n"
         "render, a stage that can be shown out of reach (a contact point beyond the\n"
         "device, a tilt past the rim, a mass point off the face, a rest the bands\n"
         "rule out), a hold longer than the time limit, a score function that fails;\n"
         "for a protocol, each condition's level under its overrides and its guidance.\n"
         "Prints one line per file: \"FILE: ok (...)\" or its problems.\n"
         "\n"
         "  --as KIND   what the files are; without it the kind is guessed: `blocks`\n"
         "              makes a protocol, `drive` with `axes` a sweep spec, `drive`\n"
         "              with `duration` a scenario, anything else a level\n"
         "  --levels DIR  protocols: where level files are looked for after the\n"
         "              protocol's folder, as `hemiroll session --levels`\n"
         "  --help      print this help\n"
         "\n"
         "Exit codes: 0 every file is clean, 2 a file has a problem or a flag is wrong.\n";
}

CheckOptionsResult parseCheckOptions(const std::vector<std::string>& args) {
  CheckOptionsResult result;
  CheckOptions& o = result.options;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .positional("file", std::numeric_limits<std::size_t>::max(), [&](const std::string& f) { o.files.push_back(f); })
      .option("--levels", cli::text(o.levelsDir, "a directory"))
      .option("--as", [&](const std::string& flag, const std::string& value) {
        if (value == "level") o.as = CheckedKind::Level;
        else if (value == "protocol") o.as = CheckedKind::Protocol;
        else if (value == "scenario") o.as = CheckedKind::Scenario;
        else if (value == "sweep") o.as = CheckedKind::Sweep;
        else return cli::needs(flag, "'level', 'protocol', 'scenario' or 'sweep'", value);
        return std::string();
      });
  result.error = reader.read(args);
  if (result.error.empty() && !o.help && o.files.empty()) result.error = "missing the file(s) to check";
  return result;
}

// The task's stage as the autopilot's goal: the same bands, by state slot.
autopilot::Goal goalOf(const task::StageDef& stage) {
  autopilot::Goal goal;
  for (const task::TargetDef& t : stage.targets) {
    if (t.variable == task::TaskVariable::omega_norm) {
      goal.omegaNormSet = true;
      goal.omegaNormTarget = t.value;
      goal.omegaNormTolerance = t.tolerance;
      continue;
    }
    const auto slot = static_cast<std::size_t>(t.variable);
    goal.set[slot] = true;
    goal.target[slot] = t.value;
    goal.tolerance[slot] = t.tolerance;
  }
  goal.hold = stage.hold;
  return goal;
}

std::string stageName(const task::StageDef& stage, std::size_t index) {
  return stage.name.empty() ? "stage " + std::to_string(index + 1)
                            : "stage " + std::to_string(index + 1) + " (\"" + stage.name + "\")";
}

// What a loaded level shows only once played. `where` prefixes each problem.
// `device`: the device whose stiffness the coupling is held to (the bot's
// desk device where no profile names one); nullptr: checked elsewhere.
void checkLoadedLevel(script::LoadedLevel& level, const std::string& where, std::vector<std::string>& problems,
                      const haptics::DeviceSpec* device) {
  const task::LevelDef& def = level.def;
  // A coupling stiffer than the device renders stably (the servo loop
  // refuses it when the trial starts).
  if (device != nullptr)
    if (const std::string why = haptics::ServoLoop::couplingProblem(def.coupling, *device); !why.empty())
      problems.push_back(where + ": force: " + why);
  autopilot::Workspace workspace;
  const script::BotLevelInfo info = botLevelInfo(def);
  workspace.centre = physics::vec3Of(info.workspaceCentre);
  workspace.radius = info.workspaceRadius;
  for (std::size_t i = 0; i < def.task.stages.size(); ++i) {
    const task::StageDef& stage = def.task.stages[i];
    const std::string name = stageName(stage, i);
    if (stage.hold >= def.task.timeLimit) {
      char line[160];
      std::snprintf(line, sizeof line, " asks for a hold of %.6g s, not shorter than the time limit of %.6g s", stage.hold,
                    def.task.timeLimit);
      problems.push_back(where + ": " + name + line);
    }
    if (const std::string why = autopilot::unreachableReason(goalOf(stage), def.params, workspace);
        !why.empty())
      problems.push_back(where + ": " + name + " cannot be won: " + why);
  }
  if (def.scoring.hasScoreFunction && level.script) {
    // The score function on the summaries a trial can end with: won at
    // half the time limit, failed at the limit.
    for (const bool won : {true, false}) {
      // A summary a trial could end with: the last stage's components at
      // half their bands, paths and effort of a plausible trial.
      task::TrialSummary s;
      s.outcome = won ? task::TrialOutcome::Success : task::TrialOutcome::Failure;
      s.reason = won ? "target held" : "time limit reached";
      s.time = won ? 0.5 * def.task.timeLimit : def.task.timeLimit;
      s.ticks = static_cast<long long>(std::llround(s.time * 1000.0));
      s.stageCount = static_cast<int>(def.task.stages.size());
      s.stagesPassed = won ? s.stageCount : 0;
      s.contactPath = 0.1;
      s.pointPath = 0.1;
      s.effort = 1.0;
      s.smoothness = 1.0;
      s.bestMargin = s.finalMargin = won ? 0.5 : -0.5;
      if (!def.task.stages.empty())
        for (const task::TargetDef& t : def.task.stages.back().targets) {
          task::ComponentStatus c;
          c.variable = t.variable;
          c.target = t.value;
          c.tolerance = t.tolerance;
          c.error = 0.5 * t.tolerance;
          c.margin = 0.5 * t.tolerance;
          c.inside = true;
          s.finalComponents.push_back(c);
        }
      const script::ScoreResult r = level.script->score(s);
      if (!r.error.empty()) {
        problems.push_back(where + ": the score function fails on a " + (won ? "won" : "failed") +
                           " trial made up for the check (half the time limit, every band at half): " + r.error);
        break;
      }
      if (r.score && !std::isfinite(*r.score))
        problems.push_back(where + ": the score function gives a value that is not a finite number for a " +
                           (won ? "won" : "failed") + " trial made up for the check");
    }
  }
}

std::string readSource(const std::string& path) {
  return files::readCheckedFile(path, files::kLuaSource);
}

std::vector<std::string> checkProtocol(const std::string& path, const std::string& levelsDir) {
  std::vector<std::string> problems;
  script::ProtocolLoadOptions loadOptions;
  loadOptions.levelsDir = levelsDir;
  const task::ProtocolDef protocol = script::ProtocolLoader(loadOptions).loadFile(path);
  (void)task::expandProtocol(protocol, protocol.seed);
  // The study's device: every condition's coupling must be one it renders.
  std::optional<task::DeviceProfileDef> device;
  if (!protocol.deviceProfile.empty()) {
    try {
      device = loadProtocolDeviceProfile(protocol.deviceProfile, path);
    } catch (const script::ScriptError& e) {
      problems.push_back(path + ": device_profile: " + e.what());
    }
  }
  // Every condition as written, and again as each group that changes its
  // block plays it.
  std::vector<const task::GroupDef*> groups = {nullptr};
  for (const task::GroupDef& g : protocol.groups) groups.push_back(&g);
  for (const task::GroupDef* group : groups)
    for (std::size_t b = 0; b < protocol.blocks.size(); ++b) {
      const task::BlockDef& block = protocol.blocks[b];
      if (group != nullptr && std::none_of(group->changes.begin(), group->changes.end(), [&](const task::GroupChange& c) {
            return c.block == static_cast<int>(b);
          }))
        continue;
      for (std::size_t c = 0; c < block.conditions.size(); ++c) {
        const task::ConditionDef condition = task::conditionInGroup(block.conditions[c], static_cast<int>(b), group);
        const std::string where = path + ": " + (group ? "group \"" + group->name + "\", " : std::string()) +
                                  "block " + std::to_string(b + 1) + " (\"" + block.name + "\"), condition " +
                                  std::to_string(c + 1) + " (\"" + condition.label + "\", " + condition.levelPath + ")";
        try {
          script::LevelLoadOptions options;
          options.adjust = [&](task::LevelDef& level) { task::applyTrialOverrides(condition.overrides, level); };
          script::LoadedLevel level = script::LevelLoader(options).loadFile(condition.levelPath);
          const haptics::DeviceSpec played = device ? deviceSpecOf(*device) : botDeviceSpec();
          // With a profile its refusal below says it in one sentence.
          checkLoadedLevel(level, where, problems, device ? nullptr : &played);
          if (device)
            if (const std::string refusal = couplingRefusal(*device, level.def.coupling, where); !refusal.empty())
              problems.push_back(refusal);
          const haptics::GuidanceDef guidance = guidanceOf(condition.overrides, 1);
          if (const std::string why = haptics::guidanceProblem(guidance, played); !why.empty())
            problems.push_back(where + ": guidance " + why);
        } catch (const std::exception& e) {
          problems.push_back(where + ": " + e.what());
        }
      }
    }
  if (!protocol.participantsFile.empty()) {
    try {
      (void)readParticipantsFile(protocol.participantsFile, protocol);
    } catch (const std::exception& e) {
      problems.push_back(e.what());
    }
  }
  return problems;
}

}  // namespace

CheckedKind guessKind(const std::string& source) {
  // A key at the start of a line or after `{` or `,`, followed by `=`.
  const auto has = [&source](const char* key) {
    return std::regex_search(source, std::regex(std::string("(^|[{,\\s])") + key + "\\s*="));
  };
  if (has("blocks")) return CheckedKind::Protocol;
  if (has("drive") && has("axes")) return CheckedKind::Sweep;
  if (has("drive") && has("duration")) return CheckedKind::Scenario;
  return CheckedKind::Level;
}

std::vector<std::string> checkFile(const std::string& path, CheckedKind kind, const std::string& levelsDir) {
  try {
    switch (kind) {
      case CheckedKind::Level: {
        script::LoadedLevel level = script::LevelLoader().loadFile(path);
        std::vector<std::string> problems;
        const haptics::DeviceSpec desk = botDeviceSpec();
        checkLoadedLevel(level, path, problems, &desk);
        return problems;
      }
      case CheckedKind::Protocol: return checkProtocol(path, levelsDir);
      case CheckedKind::Scenario: (void)script::ScenarioLoader().loadFile(path); return {};
      case CheckedKind::Sweep: (void)script::SweepLoader().loadFile(path); return {};
    }
  } catch (const std::exception& e) {
    // Loaders name the file and line themselves; a file error names the file.
    const std::string what = e.what();
    return {what.rfind(path, 0) == 0 ? what : path + ": " + what};
  }
  return {};
}

int runCheckCommand(const std::vector<std::string>& args) {
  const CheckOptionsResult parsed = parseCheckOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning(kPrefix, parsed, checkUsage())) return *exit;
  bool clean = true;
  for (const std::string& path : parsed.options.files) {
    CheckedKind kind = CheckedKind::Level;
    if (parsed.options.as) {
      kind = *parsed.options.as;
    } else {
      try {
        kind = guessKind(readSource(path));
      } catch (const std::exception& e) {
        const std::string what = e.what();
        std::cout << (what.rfind(path, 0) == 0 ? what : path + ": " + what) << "\n";
        clean = false;
        continue;
      }
    }
    const std::vector<std::string> problems = checkFile(path, kind, parsed.options.levelsDir);
    if (problems.empty()) {
      std::cout << path << ": ok (" << kindName(kind) << ")\n";
      continue;
    }
    clean = false;
    std::cout << path << ": " << problems.size() << (problems.size() == 1 ? " problem" : " problems") << " (as a "
              << kindName(kind) << ")\n";
    for (const std::string& p : problems) std::cout << "  " << p << "\n";
  }
  std::cout.flush();
  return clean ? kExitOk : kExitUsage;
}

}  // namespace hemiroll::game
