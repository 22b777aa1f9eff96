#include "game/commands/SessionCommand.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "engine/script/BotScript.h"
#include "engine/script/ScriptError.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/commands/SessionOptions.h"
#include "game/trial/BotTrial.h"
#include "game/trial/BuiltinBots.h"
#include "game/trial/DeviceProfiles.h"
#include "game/trial/DeviceTrial.h"
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

std::string trialLine(const ManifestTrial& t, const TrialResult& r, const DeviceTrial* device) {
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
  if (device) {  // a participant at a device: the stop in words and the packet counts
    const haptics::UdpBridgeCounters c = device->counters();
    line.add("stop", device->stopWords()).add("packets_received", static_cast<long long>(c.accepted));
    line.add("packets_lost", static_cast<long long>(c.lost)).add("packets_out_of_order", static_cast<long long>(c.outOfOrder));
    line.add("packets_late", static_cast<long long>(c.late)).add("packets_malformed", static_cast<long long>(c.malformed));
  }
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
  if (const auto& profile = session.deviceProfile()) {
    settings.device = deviceSpecOf(*profile);
    settings.safety = safetyOf(*profile);
  }
  std::unique_ptr<BotTrial> playing;
  try {
    playing = std::make_unique<BotTrial>(level, *bot, settings);
  } catch (const std::invalid_argument& e) {
    // A coupling the device cannot render stably, found when the loop is built.
    throw SessionError(SessionError::Kind::BadInput, trial.levelFile + " (" + trial.trialId + "): " + e.what());
  }
  const std::unique_ptr<TrialRecording> recording =
      session.recordNext(level.def, playing->rig().loopDef(), "bot", settings.device);
  playing->rig().record(recording->tap());
  const TrialResult result = playing->run();
  if (!result.scoreError.empty()) std::cerr << "hemiroll session: " << trial.trialId << ": " << result.scoreError << "\n";
  if (!result.endCallbackError.empty())
    std::cerr << "hemiroll session: " << trial.trialId << ": " << result.endCallbackError << "\n";
  session.finishNext(*recording, result, std::nullopt, deviceResultFields(nullptr));
  return result;
}

// One trial of the session at a device behind the bridge, recorded; prints
// its line. Throws SessionError.
TrialResult playAtDevice(ResearchSession& session, const SessionOptions& o) {
  const ManifestTrial& trial = session.nextTrial();
  script::LoadedLevel level = session.loadNextLevel();
  DeviceTrialDef def;
  def.bridge.port = static_cast<std::uint16_t>(o.port);
  def.clientTimeout = o.clientTimeout;
  if (const auto& profile = session.deviceProfile()) {
    def.bridge.spec = deviceSpecOf(*profile);
    def.safety = safetyOf(*profile);
  }
  std::unique_ptr<DeviceTrial> playing;
  try {
    playing = std::make_unique<DeviceTrial>(level, def);
  } catch (const std::invalid_argument& e) {
    throw SessionError(SessionError::Kind::BadInput, trial.levelFile + " (" + trial.trialId + "): " + e.what());
  } catch (const std::runtime_error& e) {  // the bridge could not open
    throw SessionError(SessionError::Kind::Environment, e.what());
  }
  const std::unique_ptr<TrialRecording> recording =
      session.recordNext(level.def, playing->rig().loopDef(), "udp", def.bridge.spec);
  playing->rig().record(recording->tap());
  const TrialResult result = playing->run();
  if (!result.scoreError.empty()) std::cerr << "hemiroll session: " << trial.trialId << ": " << result.scoreError << "\n";
  session.finishNext(*recording, result, playing->timing(), deviceResultFields(playing.get()),
                     deviceOutcomeFields(*playing));
  std::printf("%s\n", trialLine(trial, result, playing.get()).c_str());
  std::fflush(stdout);
  return result;
}

}  // namespace

int runSessionCommand(const std::vector<std::string>& args) {
  const SessionOptionsResult parsed = parseSessionOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning("hemiroll session: ", parsed, sessionUsage())) return *exit;
  const SessionOptions& o = parsed.options;
  const bool atDevice = o.device == "udp";
  if (!o.botPath && !atDevice)
    return fail(kExitUsage,
                "people play sessions in the game window: run `hemiroll play`, open Research session (R), pick "
                "the protocol, enter the participant and start; here a bot plays every trial (--bot BOT.lua), or a "
                "participant at a device behind the UDP bridge (--device udp)");
  try {
    // A broken bot is refused before anything is written.
    if (o.botPath && !isBuiltinBot(*o.botPath)) script::BotScript{*o.botPath};
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
  request.deviceProfile = o.deviceProfile;
  Tally tally;
  try {
    ResearchSession session(request);
    haptics::DeviceSpec device = atDevice ? haptics::UdpBridgeDef{}.spec : botDeviceSpec();
    if (session.deviceProfile()) device = deviceSpecOf(*session.deviceProfile());
    if (const std::string problem = session.couplingProblem(device); !problem.empty())
      return fail(kExitUsage, problem);
    session.begin(atDevice ? std::string("udp") : *o.botPath);
    if (!session.lockNote().empty()) std::cerr << "hemiroll session: " << session.lockNote() << "\n";
    for (const auto& [trialId, reason] : session.interrupted())
      std::cerr << "hemiroll session: " << trialId << " was " << reason << "; its files were moved aside (*.aborted-N)\n";
    while (!session.complete() && !session.stopsHere()) {
      if (const ManifestBreak* pause = session.pendingBreak()) {
        std::cerr << "hemiroll session: break before block " << session.nextTrial().block << ": " << pause->message
                  << (atDevice ? "\n" : " (bots do not rest)\n");
        if (atDevice)  // a person rests at least the protocol's break
          std::this_thread::sleep_for(std::chrono::duration<double>(pause->minDuration));
      }
      const ManifestTrial trial = session.nextTrial();
      if (atDevice) {
        std::cerr << "hemiroll session: " << trial.trialId << ": " << session.instructionsOf(trial) << "\n";
        const TrialResult result = playAtDevice(session, o);
        ++tally.ran;
        tally.successes += result.outcome == script::TrialOutcome::Success;
        continue;
      }
      const TrialResult result = playNext(session, *o.botPath);
      ++tally.ran;
      tally.successes += result.outcome == script::TrialOutcome::Success;
      std::printf("%s\n", trialLine(trial, result, nullptr).c_str());
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
