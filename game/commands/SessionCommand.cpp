#include "game/commands/SessionCommand.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "engine/script/BotScript.h"
#include "engine/script/ScriptError.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/commands/SessionOptions.h"
#include "game/trial/BotTrial.h"
#include "game/trial/BuiltinBots.h"
#include "game/trial/JsonLine.h"
#include "game/research/ResearchSession.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

namespace {

int fail(int code, const std::string& message) {
  std::cerr << "hemiroll session: " << message << "\n";
  return code;
}

int exitCodeOf(const SessionError& e) { return e.kind() == SessionError::Kind::BadInput ? kExitUsage : kExitFailure; }

std::string trialLine(const ManifestTrial& t, const TrialResult& r) {
  JsonLine line;
  line.add("event", "trial").add("trial", static_cast<long long>(t.index)).add("trial_id", t.trialId);
  line.add("block", static_cast<long long>(t.block)).add("block_name", t.blockName);
  line.add("repetition", static_cast<long long>(t.repetition)).add("condition", t.conditionLabel);
  line.add("level", t.levelFile).add("method", t.method);
  line.add("kr_N_per_m", t.stiffness).add("kv_N_s_per_m", t.damping).add("alpha", t.alpha);
  line.add("outcome", script::trialOutcomeName(r.outcome)).add("reason", r.reason).add("time_s", r.time, 6);
  if (r.score)
    line.add("score", *r.score);  // non-finite: null
  else
    line.addNull("score");
  line.add("medal", script::medalName(r.medal)).add("ticks", r.ticks).add("wall_time_s", r.wallTime, 6);
  return line.str();
}

struct Tally {
  long long ran = 0, successes = 0;
};

std::string summaryLine(const ResearchSession& s, const Tally& tally, bool stopped) {
  JsonLine line;
  line.add("event", "summary").add("experiment", s.manifest().experiment);
  line.add("participant", s.manifest().participant).add("session", s.manifest().session);
  line.add("folder", s.folder().string());
  line.add("trials", static_cast<long long>(s.trialCount())).add("done", static_cast<long long>(s.done()));
  line.add("kept", static_cast<long long>(s.keptFromEarlier())).add("ran", tally.ran);
  line.add("successes", tally.successes).add("failures", tally.ran - tally.successes);
  line.add("moved_aside", static_cast<long long>(s.interrupted().size()));
  line.addBool("complete", s.complete()).addBool("stopped_at_break", stopped);
  return line.str();
}

// One trial of the session, headless, recorded. Throws SessionError.
TrialResult playNext(ResearchSession& session, const std::string& botPath) {
  const ManifestTrial& trial = session.nextTrial();
  script::LoadedLevel level = session.loadNextLevel();
  std::unique_ptr<script::BotPolicy> bot;
  try {
    bot = makeBot(botPath, trial.seed);
  } catch (const script::ScriptError& e) {
    throw SessionError(SessionError::Kind::BadInput, e.what());
  }
  TrialSettings settings;
  settings.seed = trial.seed;
  settings.guidance = trial.guidance;
  std::unique_ptr<BotTrial> playing;
  try {
    playing = std::make_unique<BotTrial>(level, *bot, settings);
  } catch (const std::invalid_argument& e) {
    // A coupling the device cannot render stably, found when the loop is built.
    throw SessionError(SessionError::Kind::BadInput, trial.levelFile + " (" + trial.trialId + "): " + e.what());
  }
  const std::unique_ptr<TrialRecording> recording =
      session.recordNext(level.def, playing->rig().loopDef(), "bot", botDeviceSpec());
  playing->rig().record(recording->tap());
  const TrialResult result = playing->run();
  if (!result.scoreError.empty()) std::cerr << "hemiroll session: " << trial.trialId << ": " << result.scoreError << "\n";
  if (!result.endCallbackError.empty())
    std::cerr << "hemiroll session: " << trial.trialId << ": " << result.endCallbackError << "\n";
  session.finishNext(*recording, result);
  return result;
}

}  // namespace

int runSessionCommand(const std::vector<std::string>& args) {
  const SessionOptionsResult parsed = parseSessionOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning("hemiroll session: ", parsed, sessionUsage())) return *exit;
  const SessionOptions& o = parsed.options;
  if (!o.botPath)
    return fail(kExitUsage,
                "people play sessions in the game window: run `hemiroll play`, open Research session (R), pick "
                "the protocol, enter the participant and start; here a bot plays every trial (--bot BOT.lua)");
  try {
    // A broken bot is refused before anything is written.
    if (!isBuiltinBot(*o.botPath)) script::BotScript{*o.botPath};
  } catch (const script::ScriptError& e) {
    return fail(kExitUsage, e.what());
  }

  SessionRequest request;
  request.protocolPath = o.protocolPath;
  request.levelsDir = o.levelsDir;
  request.participant = o.participant;
  request.session = o.session;
  if (o.dataRoot) request.dataRoot = *o.dataRoot;
  request.seed = o.seed;
  Tally tally;
  try {
    ResearchSession session(request);
    if (const std::string problem = session.couplingProblem(botDeviceSpec()); !problem.empty())
      return fail(kExitUsage, problem);
    session.begin(*o.botPath);
    if (!session.lockNote().empty()) std::cerr << "hemiroll session: " << session.lockNote() << "\n";
    for (const auto& [trialId, reason] : session.interrupted())
      std::cerr << "hemiroll session: " << trialId << " was " << reason << "; its files were moved aside (*.aborted-N)\n";
    while (!session.complete() && !session.stopsHere()) {
      if (const ManifestBreak* pause = session.pendingBreak())
        std::cerr << "hemiroll session: break before block " << session.nextTrial().block << ": " << pause->message
                  << " (bots do not rest)\n";
      const ManifestTrial trial = session.nextTrial();
      const TrialResult result = playNext(session, *o.botPath);
      ++tally.ran;
      tally.successes += result.outcome == script::TrialOutcome::Success;
      std::printf("%s\n", trialLine(trial, result).c_str());
      std::fflush(stdout);
    }
    std::printf("%s\n", summaryLine(session, tally, !session.complete()).c_str());
    if (!session.complete())
      std::cerr << "hemiroll session: the sitting ends at a break (" << session.pendingBreak()->message
                << "); run the same command again to continue\n";
  } catch (const SessionError& e) {
    return fail(exitCodeOf(e), e.what());
  }
  return kExitOk;
}

}  // namespace hemiroll::game
