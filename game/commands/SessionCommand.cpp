#include "game/commands/SessionCommand.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "engine/script/BotScript.h"
#include "engine/script/ScriptError.h"
#include "engine/haptics/devices/DeviceNames.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/commands/SessionOptions.h"
#include "game/trial/BotTrial.h"
#include "game/trial/BuiltinBots.h"
#include "game/trial/DeviceProfiles.h"
#include "game/trial/DeviceTrial.h"
#include "game/trial/JsonLine.h"
#include "engine/script/ProtocolLoader.h"
#include "game/research/session/ResearchSession.h"
#include "game/research/session/SessionBotMemory.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

namespace {

int fail(int code, const std::string& message) {
  std::cerr << "hemiroll session: " << message << "\n";
  return code;
}

int exitCodeOf(const SessionError& e) { return e.kind() == SessionError::Kind::BadInput ? kExitUsage : kExitFailure; }

std::string trialLine(const std::string& participant, const std::string& group, const ManifestTrial& t,
                      const TrialResult& r, const DeviceTrial* device) {
  JsonLine line;
  line.add("event", "trial").add("trial", static_cast<long long>(t.index)).add("trial_id", t.trialId);
  line.add("block", static_cast<long long>(t.block)).add("block_name", t.blockName);
  line.add("repetition", static_cast<long long>(t.repetition)).add("condition", t.conditionLabel);
  line.add("level", t.levelFile).add("method", t.method);
  line.add("kr_N_per_m", t.stiffness).add("kv_N_s_per_m", t.damping).add("alpha", t.alpha);
  line.add("outcome", task::trialOutcomeName(r.outcome)).add("reason", r.reason).add("time_s", r.time, 6);
  if (r.score)
    line.add("score", *r.score);  // non-finite: null
  else
    line.addNull("score");
  line.add("medal", task::medalName(r.medal)).add("ticks", r.ticks).add("wall_time_s", r.wallTime, 6);
  line.add("participant", participant).add("group", group);
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

// The trial's place, as a bot's init gets it (BotLevelInfo::place).
script::TrialPlace placeOf(const ResearchSession& session, const ManifestTrial& t) {
  script::TrialPlace p;
  p.inSession = true;
  p.trialIndex = t.index;
  p.block = t.block;
  p.blockName = t.blockName;
  p.trialInBlock = t.trialInBlock;
  p.condition = t.condition;
  p.conditionLabel = t.conditionLabel;
  p.group = session.manifest().group;
  p.guidance = haptics::guidanceKindName(t.guidance.kind);
  p.guidanceFade = t.guidance.kind == haptics::GuidanceKind::None ? 0.0 : t.guidance.scale;
  return p;
}

// One trial of the session, headless, recorded; the bot's memory is
// written before the results row (SessionBotMemory.h). Throws SessionError.
TrialResult playNext(ResearchSession& session, const SessionOptions& o, script::BotMemory& memory) {
  const ManifestTrial& trial = session.nextTrial();
  script::LoadedLevel level = session.loadNextLevel();
  std::unique_ptr<script::BotPolicy> bot;
  try {
    BuiltinBotOptions builtin;
    builtin.human = o.human;
    bot = makeBot(*o.botPath, trial.seed, builtin);
  } catch (const script::ScriptError& e) {
    throw SessionError(SessionError::Kind::BadInput, e.what());
  }
  const script::BotMemory before = memory;
  TrialSettings settings;
  settings.seed = trial.seed;
  settings.guidance = trial.guidance;
  settings.place = placeOf(session, trial);
  settings.memory = &memory;
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
  try {
    bot->endTrial();  // a Lua bot's level.memory back into the participant's memory
  } catch (const script::ScriptError& e) {
    memory = before;
    std::cerr << "hemiroll session: " << trial.trialId << ": " << e.what() << " (the memory is kept as it was)\n";
  }
  if (!result.scoreError.empty()) std::cerr << "hemiroll session: " << trial.trialId << ": " << result.scoreError << "\n";
  if (!result.endCallbackError.empty())
    std::cerr << "hemiroll session: " << trial.trialId << ": " << result.endCallbackError << "\n";
  writeBotMemory(session.folder(), trial.index, memory, before);
  session.finishNext(*recording, result, std::nullopt, deviceResultFields(nullptr));
  return result;
}

// One trial of the session at a device behind the bridge, recorded; prints
// its line. Throws SessionError.
TrialResult playAtDevice(ResearchSession& session, const SessionOptions& o, const std::string& participant) {
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
      session.recordNext(level.def, playing->rig().loopDef(), haptics::kUdpDevice, def.bridge.spec);
  playing->rig().record(recording->tap());
  const TrialResult result = playing->run();
  // No device, no trial: nothing was played, so nothing is data. The trial
  // stays unfinished (its files are moved aside when the session resumes)
  // and the sitting stops here.
  if (!playing->clientCame())
    throw SessionError(SessionError::Kind::Environment,
                       trial.trialId + ": " + result.reason + ". The trial was not played and is not counted: run "
                       "the same command again once the device's client runs, and the session resumes at it");
  if (!result.scoreError.empty()) std::cerr << "hemiroll session: " << trial.trialId << ": " << result.scoreError << "\n";
  session.finishNext(*recording, result, playing->timing(), deviceResultFields(playing.get()),
                     deviceOutcomeFields(*playing));
  std::printf("%s\n", trialLine(participant, session.manifest().group, trial, result, playing.get()).c_str());
  std::fflush(stdout);
  return result;
}

// One participant's sitting: every trial to the end or to a stop break.
// Returns the exit code.
int runParticipant(const SessionOptions& o, const SessionRequest& request) {
  Tally tally;
  try {
    ResearchSession session(request);
    const bool atDevice = o.device == haptics::kUdpDevice;
    haptics::DeviceSpec device = atDevice ? haptics::UdpBridgeDef{}.spec : botDeviceSpec();
    if (session.deviceProfile()) device = deviceSpecOf(*session.deviceProfile());
    if (const std::string problem = session.couplingProblem(device); !problem.empty())
      return fail(kExitUsage, problem);
    std::string memoryNote;
    script::BotMemory memory = restoreBotMemory(session.folder(), session.done(), memoryNote);
    session.begin(atDevice ? std::string(haptics::kUdpDevice) : *o.botPath);
    if (!session.lockNote().empty()) std::cerr << "hemiroll session: " << session.lockNote() << "\n";
    if (!memoryNote.empty()) std::cerr << "hemiroll session: " << memoryNote << "\n";
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
        if (const std::string words = session.instructionsOf(trial); !words.empty())
          std::cerr << "hemiroll session: " << trial.trialId << ": " << words << "\n";
        const TrialResult result = playAtDevice(session, o, request.participant);
        ++tally.ran;
        tally.successes += result.outcome == task::TrialOutcome::Success;
        continue;
      }
      const TrialResult result = playNext(session, o, memory);
      ++tally.ran;
      tally.successes += result.outcome == task::TrialOutcome::Success;
      std::printf("%s\n", trialLine(request.participant, session.manifest().group, trial, result, nullptr).c_str());
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

// "sim-01" .. "sim-20": as many digits as N has, at least two.
std::string cohortId(const std::string& prefix, int k, int n) {
  const int digits = std::max(2, static_cast<int>(std::to_string(n).size()));
  std::string number = std::to_string(k);
  number.insert(0, static_cast<std::size_t>(std::max(0, digits - static_cast<int>(number.size()))), '0');
  return prefix + "-" + number;
}

}  // namespace

int runSessionCommand(const std::vector<std::string>& args) {
  const SessionOptionsResult parsed = parseSessionOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning("hemiroll session: ", parsed, sessionUsage())) return *exit;
  const SessionOptions& o = parsed.options;
  const bool atDevice = o.device == haptics::kUdpDevice;
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
  if (o.participants == 0) return runParticipant(o, request);

  // A cohort: participant k with the plan's seed + k - 1, so that each
  // plays its own shuffles and its own noise.
  std::uint64_t base = 0;
  if (o.seed) {
    base = *o.seed;
  } else {
    try {
      script::ProtocolLoadOptions options;
      options.levelsDir = o.levelsDir;
      base = script::ProtocolLoader(options).loadFile(o.protocolPath).seed;
    } catch (const script::ScriptError& e) {
      return fail(kExitUsage, e.what());
    }
  }
  const auto start = std::chrono::steady_clock::now();
  for (int k = 1; k <= o.participants; ++k) {
    request.participant = cohortId(o.participant, k, o.participants);
    request.seed = (base + static_cast<std::uint64_t>(k - 1)) & 0x7fffffffffffffffULL;
    if (const int code = runParticipant(o, request); code != kExitOk) return code;
  }
  JsonLine line;
  line.add("event", "cohort").add("participants", static_cast<long long>(o.participants));
  line.add("wall_time_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3);
  std::printf("%s\n", line.str().c_str());
  return kExitOk;
}

}  // namespace hemiroll::game
