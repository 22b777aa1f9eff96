#include "game/research/session/ResearchSession.h"

#include <algorithm>
#include <map>

#include "engine/files/PrintableName.h"
#include "engine/record/ContentHash.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/ResultsFile.h"
#include "engine/script/ProtocolLoader.h"
#include "engine/task/ProtocolPlan.h"
#include "engine/script/ScriptError.h"
#include "game/research/session/GroupAssignment.h"
#include "game/research/session/ParticipantsFile.h"
#include "game/trial/DeviceProfiles.h"
#include "game/trial/DeviceTrial.h"
#include "game/trial/ReplayCapture.h"
#include "game/research/session/SessionFolder.h"
#include "game/research/session/SessionResume.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void badInput(const std::string& message) { throw SessionError(SessionError::Kind::BadInput, message); }
[[noreturn]] void environment(const std::string& message) {
  throw SessionError(SessionError::Kind::Environment, message);
}

std::string number(double v) {
  std::string out;
  record::appendDouble(v, out);
  return out;
}

// What the session needs of a level file: loaded once per file.
struct LevelFacts {
  std::string name, hash;
  physics::CouplingDef coupling;
  double timeLimit = 0.0;
};

LevelFacts factsOf(const std::string& path, const script::SandboxLimits& limits) {
  try {
    script::LevelLoadOptions options;
    options.limits = limits;
    const script::LoadedLevel level = script::LevelLoader(options).loadFile(path);
    return {level.def.name, record::fileContentHash(path), level.def.coupling, level.def.task.timeLimit};
  } catch (const script::ScriptError& e) {
    badInput(e.what());
  }
}

}  // namespace

ResearchSession::ResearchSession(const SessionRequest& request) {
  if (const std::string problem = checkFolderId(request.participant, "participant id"); !problem.empty())
    badInput(problem);
  if (const std::string problem = checkFolderId(request.session, "session id"); !problem.empty()) badInput(problem);
  try {
    script::ProtocolLoadOptions options;
    options.levelsDir = request.levelsDir;
    options.limits = request.loadLimits;
    protocol_ = script::ProtocolLoader(options).loadFile(request.protocolPath);
  } catch (const script::ScriptError& e) {
    badInput(e.what());
  }
  const std::string& named = protocol_.deviceProfile;
  if (request.deviceProfile && !named.empty() && *request.deviceProfile != named)
    badInput(request.protocolPath + " names the device profile '" + named + "', not '" + *request.deviceProfile +
             "': a study runs on the device its protocol names (leave --device-profile out, or change the protocol)");
  if (const std::string name = request.deviceProfile.value_or(named); !name.empty()) {
    try {
      profile_ = request.deviceProfile ? loadDeviceProfile(name) : loadProtocolDeviceProfile(name, request.protocolPath);
    } catch (const script::ScriptError& e) {
      badInput(e.what());
    }
  }
  folder_ = sessionFolder(request.dataRoot.empty() ? defaultSessionsRoot() : request.dataRoot, protocol_.experiment,
                          request.participant, request.session);
  manifest_.participant = request.participant;
  manifest_.session = request.session;

  std::error_code ec;
  const fs::path manifestPath = folder_ / kManifestFile;
  std::optional<SessionManifest> previous;
  if (fs::exists(manifestPath, ec)) {
    try {
      previous = SessionManifest::fromJson(record::readWholeFile(manifestPath, files::kSessionManifest), manifestPath.string());
    } catch (const std::exception& e) {
      environment(e.what());
    }
  } else if (fs::exists(folder_, ec)) {
    // A lock file alone is a session that ended before its manifest.
    for (const fs::directory_entry& entry : fs::directory_iterator(folder_, ec))
      if (entry.path().filename() != kLockFile)
        environment(folder_.string() + " holds files but no " + kManifestFile + ": it is not a session folder");
  }
  if (previous && request.seed && *request.seed != previous->seed)
    badInput("session '" + request.session + "' of participant '" + request.participant + "' was started with seed " +
             std::to_string(previous->seed) + ", not " + std::to_string(*request.seed) +
             "; leave --seed out to resume it, or start a new session");
  if (previous) {
    keepAssignment(*previous);
  } else {
    const ParticipantAssignment a =
        assignParticipant(protocol_, folder_.parent_path().parent_path(), request.participant, request.session);
    manifest_.group = a.group;
    manifest_.blockOrder = a.order;
    manifest_.assignedBy = a.how;
    manifest_.participantInfo = a.info;
  }
  buildPlan(request, previous ? previous->seed : request.seed.value_or(protocol_.seed));
  if (!previous) return;

  checkAgainst(*previous);
  resumed_ = true;
  // The manifest keeps what the session started with; sittings and moved
  // files accumulate.
  const std::vector<std::pair<std::string, task::TrialOverrides>> current = std::move(trials_);
  manifest_ = *previous;
  trials_ = current;
  const ResumePoint point = findResumePoint(folder_, manifest_.plan);  // results.csv checked readable
  checkResultsColumns(*previous);
  done_ = kept_ = point.done;
  interrupted_ = point.interrupted;
}

haptics::GuidanceDef guidanceOf(const task::TrialOverrides& overrides, int trialInBlock) {
  haptics::GuidanceDef g;
  if (!overrides.guidance) {
    g.scale = 0.0;  // results show fade 0: no guidance at all
    return g;
  }
  const task::GuidanceSpec& spec = *overrides.guidance;
  haptics::parseGuidanceKind(spec.kind, g.kind);  // the loader accepts only the three names
  g.stiffness = spec.stiffness;
  g.damping = spec.damping;
  g.maxError = spec.maxError;
  g.scale = spec.fadeAt(trialInBlock);
  return g;
}

void ResearchSession::keepAssignment(const SessionManifest& previous) {
  const std::string which = "session '" + previous.session + "' of participant '" + previous.participant + "'";
  if (!previous.group.empty() && protocol_.group(previous.group) == nullptr)
    badInput(which + " is in group '" + previous.group + "', which the protocol no longer has");
  if (protocol_.assignment == task::Assignment::ParticipantsFile) {
    const ParticipantsTable table = readParticipantsFile(protocol_.participantsFile, protocol_);
    const ParticipantRow* row = table.find(previous.participant);
    if (row == nullptr)
      badInput("participant '" + previous.participant + "' is no longer in " + protocol_.participantsFile + ", and " +
               which + " started in group '" + previous.group + "'; put their line back to resume it");
    if (row->group != previous.group)
      badInput(protocol_.participantsFile + ":" + std::to_string(row->line) + ": column 'group': '" + row->group +
               "', but " + which + " started in group '" + previous.group +
               "'; a participant keeps their group: correct the file, or start a new participant id");
  }
  manifest_.group = previous.group;
  manifest_.blockOrder = previous.blockOrder;
  manifest_.assignedBy = previous.assignedBy;
  manifest_.participantInfo = previous.participantInfo;
}

void ResearchSession::checkResultsColumns(const SessionManifest& previous) const {
  std::vector<std::string> found;
  try {
    found = record::ResultsFile(folder_ / "results.csv").read().columns;
  } catch (const record::RecordError& e) {
    environment(e.what());
  }
  if (found.empty() || manifest_.plan.empty()) return;  // no rows yet: nothing to line up with
  record::ResultsRow row;
  row.extra = resultsFields(manifest_.plan.front(), TrialResult{}, {});
  const std::vector<std::string> wanted = record::ResultsFile::columns(row);
  if (found == wanted) return;
  std::string missing, extra;
  for (const std::string& c : wanted)
    if (std::find(found.begin(), found.end(), c) == found.end()) missing += (missing.empty() ? "" : ", ") + c;
  for (const std::string& c : found)
    if (std::find(wanted.begin(), wanted.end(), c) == wanted.end()) extra += (extra.empty() ? "" : ", ") + c;
  std::string differences = missing.empty() ? "" : "it lacks " + missing;
  if (!extra.empty()) differences += (differences.empty() ? "it has " : "; it has ") + extra + ", which this version does not write";
  if (differences.empty()) differences = "the same columns in another order";
  badInput((folder_ / "results.csv").string() + " of session '" + previous.session + "' of participant '" +
           previous.participant + "' was started by hemiroll " + previous.softwareVersion +
           " with other columns than this version writes (" + differences +
           "): rows of the two would not line up, so this version cannot resume it. Finish the session with the "
           "version that started it, or start a new session (--session with a new id) to run the protocol afresh");
}

void ResearchSession::buildPlan(const SessionRequest& request, std::uint64_t seed) {
  const task::ProtocolPlan plan = task::expandProtocol(protocol_, seed, manifest_.blockOrder);
  const task::GroupDef* group = protocol_.group(manifest_.group);
  manifest_.experiment = protocol_.experiment;
  manifest_.description = protocol_.description;
  // Paths as text (JSON, CSV): a name that is not UTF-8 is shown with \xNN.
  manifest_.protocolFile = files::printable(request.protocolPath);
  manifest_.protocolHash = record::fileContentHash(request.protocolPath);
  manifest_.protocolVersion = protocol_.version;
  manifest_.seed = seed;
  std::map<std::string, LevelFacts> levels;
  for (const task::PlannedTrial& p : plan.trials) {
    const task::ConditionDef condition =
        task::conditionInGroup(task::ProtocolPlan::conditionOf(protocol_, p), p.definedBlock - 1, group);
    auto found = levels.find(condition.levelPath);
    if (found == levels.end()) found = levels.emplace(condition.levelPath, factsOf(condition.levelPath, request.loadLimits)).first;
    const LevelFacts& level = found->second;
    const physics::CouplingDef coupling = task::overriddenCoupling(condition.overrides, level.coupling);
    ManifestTrial t;
    t.index = p.index;
    t.trialId = sessionTrialId(p.index);
    t.block = p.block;
    t.blockName = task::ProtocolPlan::blockOf(protocol_, p).name;
    t.trialInBlock = p.trialInBlock;
    t.repetition = p.repetition;
    t.condition = p.condition;
    t.conditionLabel = condition.label;
    t.levelFile = files::printable(condition.levelPath);
    t.levelName = level.name;
    t.levelHash = level.hash;
    t.method = task::couplingMethodName(coupling);
    t.stiffness = coupling.stiffness;
    t.damping = coupling.damping;
    t.alpha = coupling.alpha;
    t.timeLimit = condition.overrides.timeLimit.value_or(level.timeLimit);
    t.seed = p.seed;
    t.guidance = guidanceOf(condition.overrides, p.trialInBlock);
    if (const task::BreakDef* b = task::ProtocolPlan::breakBefore(protocol_, p))
      t.breakBefore = ManifestBreak{b->message, b->minDuration, b->stop};
    manifest_.plan.push_back(std::move(t));
    trials_.emplace_back(condition.levelPath, condition.overrides);
    definedBlocks_.push_back(p.definedBlock);
  }
}

void ResearchSession::checkAgainst(const SessionManifest& previous) const {
  const std::string which = "session '" + manifest_.session + "' of participant '" + manifest_.participant + "'";
  const std::string fix = "; finish it with the protocol and levels it started with, or start a new session";
  if (previous.protocolHash != manifest_.protocolHash)
    badInput(manifest_.protocolFile + " changed since " + which + " started (content hash " + previous.protocolHash +
             ", now " + manifest_.protocolHash + ")" + fix);
  if (previous.plan.size() != manifest_.plan.size())
    badInput("the plan of " + which + " has " + std::to_string(previous.plan.size()) + " trials, the protocol now " +
             std::to_string(manifest_.plan.size()) + fix);
  for (std::size_t i = 0; i < previous.plan.size(); ++i) {
    const ManifestTrial& was = previous.plan[i];
    const ManifestTrial& now = manifest_.plan[i];
    if (was.levelHash != now.levelHash)
      badInput(now.levelFile + " (" + now.trialId + ") changed since " + which + " started (content hash " +
               was.levelHash + ", now " + now.levelHash + ")" + fix);
    if (was.trialId != now.trialId || was.method != now.method || was.stiffness != now.stiffness ||
        was.damping != now.damping || was.alpha != now.alpha || was.timeLimit != now.timeLimit || was.seed != now.seed ||
        was.guidance.kind != now.guidance.kind || was.guidance.stiffness != now.guidance.stiffness ||
        was.guidance.damping != now.guidance.damping || was.guidance.maxError != now.guidance.maxError ||
        was.guidance.scale != now.guidance.scale)
      badInput(now.trialId + " of " + which + " is planned differently now" + fix);
  }
}

void ResearchSession::begin(const std::string& player) {
  player_ = player;
  if (complete()) return;
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (ec) environment("cannot create the session folder " + folder_.string() + ": " + ec.message());
  lock_ = std::make_unique<SessionLock>(folder_, "hemiroll session of " + manifest_.experiment + " as " + player);
  // What the constructor read may have changed before the lock was taken:
  // another session may have run in the folder meanwhile.
  const bool manifestNow = fs::exists(folder_ / kManifestFile, ec);
  const bool changed = manifestNow != resumed_ ||
                       (resumed_ && [&] {
                         const ResumePoint now = findResumePoint(folder_, manifest_.plan);
                         return now.done != done_ || now.interrupted != interrupted_;
                       }());
  if (changed) {
    lock_.reset();
    environment("the session folder " + folder_.string() +
                " changed while this session was being opened (another session ran in it); run it again");
  }
  for (const auto& [trialId, reason] : interrupted_) manifest_.aborted.push_back(moveTrialAside(folder_, trialId, reason));
  if (!resumed_) {
    manifest_.startTime = record::utcTimestamp();
    manifest_.softwareVersion = record::softwareVersion();
  }
  manifest_.sittings.push_back({record::utcTimestamp(), record::softwareVersion(), done_ + 1, player});
  try {
    record::writeFileAtomically(folder_ / kManifestFile, manifest_.toJson());
  } catch (const record::RecordError& e) {
    environment(e.what());
  }
}

const std::string& ResearchSession::lockNote() const {
  static const std::string none;
  return lock_ ? lock_->note() : none;
}

const std::string& ResearchSession::instructionsOf(const ManifestTrial& trial) const {
  return protocol_.blocks.at(static_cast<std::size_t>(definedBlocks_.at(static_cast<std::size_t>(trial.index - 1)) - 1))
      .instructions;
}

const ManifestBreak* ResearchSession::pendingBreak() const {
  if (complete() || !nextTrial().breakBefore) return nullptr;
  return &*nextTrial().breakBefore;
}

bool ResearchSession::stopsHere() const {
  const ManifestBreak* pause = pendingBreak();
  return pause != nullptr && pause->stop && ranThisSitting_ > 0;
}

std::string ResearchSession::couplingProblem(const haptics::DeviceSpec& device) const {
  for (std::size_t i = static_cast<std::size_t>(done_); i < manifest_.plan.size(); ++i) {
    const ManifestTrial& t = manifest_.plan[i];
    task::TrialOverrides planned;  // the effective coupling, as overrides of any
    planned.method = t.method;
    planned.stiffness = t.stiffness;
    planned.damping = t.damping;
    planned.alpha = t.alpha;
    const physics::CouplingDef coupling = task::overriddenCoupling(planned, {});
    if (profile_) {
      const std::string refusal = couplingRefusal(*profile_, coupling, t.levelFile + " (" + t.trialId + ", " + t.conditionLabel + ")");
      if (!refusal.empty()) return refusal;
    }
    const std::string problem = haptics::ServoLoop::couplingProblem(coupling, device);
    if (!problem.empty())
      return t.trialId + " (" + t.conditionLabel + ", " + t.levelFile + "): the " + device.name +
             " device cannot take this coupling: " + problem;
    if (const std::string guidance = haptics::guidanceProblem(t.guidance, device); !guidance.empty())
      return t.trialId + " (" + t.conditionLabel + ", " + t.levelFile + "): the " + device.name +
             " device cannot take this guidance: " + guidance;
  }
  return "";
}

script::LoadedLevel ResearchSession::loadNextLevel() const {
  const ManifestTrial& trial = nextTrial();
  const auto& planned = trials_.at(static_cast<std::size_t>(done_));
  const std::string& path = planned.first;
  const task::TrialOverrides& overrides = planned.second;  // a plain reference: clang 14 captures no structured binding
  script::LevelLoadOptions options;
  options.seed = trial.seed;
  options.adjust = [&overrides](task::LevelDef& level) { task::applyTrialOverrides(overrides, level); };
  try {
    return script::LevelLoader(options).loadFile(path);
  } catch (const script::ScriptError& e) {
    badInput(e.what());
  }
}

std::unique_ptr<TrialRecording> ResearchSession::recordNext(const task::LevelDef& level,
                                                            const haptics::ServoLoopDef& loop,
                                                            const std::string& deviceName,
                                                            const haptics::DeviceSpec& spec) const {
  const ManifestTrial& t = nextTrial();
  TrialRecordingDef def;
  def.dir = folder_.string();
  def.ids = {manifest_.participant, manifest_.session};
  def.trialId = t.trialId;
  def.taskName = manifest_.experiment;
  def.levelHash = t.levelHash;
  def.seed = t.seed;
  def.deviceName = deviceName;
  def.deviceSpec = spec;
  def.sidecarExtra = {{"experiment", manifest_.experiment},  {"protocol_file", manifest_.protocolFile},
                      {"group", manifest_.group},             {"block_order", std::to_string(manifest_.blockOrder)},
                      {"trial_index", std::to_string(t.index)}, {"block", std::to_string(t.block)},
                      {"block_name", t.blockName},            {"trial_in_block", std::to_string(t.trialInBlock)},
                      {"repetition", std::to_string(t.repetition)}, {"condition", std::to_string(t.condition)},
                      {"condition_label", t.conditionLabel},  {"level_file", t.levelFile},
                      {"player", player_},  {"device_profile", profile_ ? profile_->name : ""}};
  // A results.csv whose header this trial's row could not join is found
  // now, not after the participant has played the trial.
  try {
    record::ResultsRow row;
    row.extra = resultsFields(t, TrialResult{}, {});
    record::ResultsFile(folder_ / "results.csv").checkColumns(row);
  } catch (const record::RecordError& e) {
    environment(e.what());
  }
  try {
    return std::make_unique<TrialRecording>(def, level, loop);
  } catch (const TrialRecordingError& e) {
    environment(e.what());
  }
}

void ResearchSession::finishNext(TrialRecording& recording, const TrialResult& result,
                                 const std::optional<haptics::LoopTimingSummary>& timing,
                                 const record::Fields& device, const record::Fields& outcome) {
  record::Fields extra = resultsFields(nextTrial(), result, device);
  try {
    recording.finish(result, extra, timing, outcome);
  } catch (const TrialRecordingError& e) {
    environment(e.what());
  }
  ++done_;
  ++ranThisSitting_;
}

record::Fields ResearchSession::resultsFields(const ManifestTrial& t, const TrialResult& result,
                                              const record::Fields& device) const {
  record::Fields extra = {{"group", manifest_.group},
                          {"block_order", std::to_string(manifest_.blockOrder)},
                          {"trial_index", std::to_string(t.index)},
                          {"block", std::to_string(t.block)},
                          {"block_name", t.blockName},
                          {"trial_in_block", std::to_string(t.trialInBlock)},
                          {"repetition", std::to_string(t.repetition)},
                          {"condition", std::to_string(t.condition)},
                          {"condition_label", t.conditionLabel},
                          {"level_file", t.levelFile},
                          {"method", t.method},
                          {"kr_N_per_m", number(t.stiffness)},
                          {"kv_N_s_per_m", number(t.damping)},
                          {"alpha", number(t.alpha)},
                          {"time_limit_s", number(t.timeLimit)},
                          {"seed", std::to_string(t.seed)},
                          {"guidance", haptics::guidanceKindName(t.guidance.kind)},
                          {"guidance_stiffness_N_per_m", number(t.guidance.stiffness)},
                          {"guidance_damping_N_s_per_m", number(t.guidance.damping)},
                          {"guidance_fade", number(t.guidance.scale)}};
  for (auto& field : TrialRecording::scoreFields(result)) extra.push_back(std::move(field));
  for (auto& field : TrialRecording::measureFields(result)) extra.push_back(std::move(field));
  extra.emplace_back("ticks", std::to_string(result.ticks));
  extra.emplace_back("player", player_);
  extra.emplace_back("device_profile", profile_ ? profile_->name : "");
  // The same columns for every player (DeviceTrial.h); before the trial, their names only.
  for (auto& field : device.empty() ? deviceResultFields(nullptr, "") : device) extra.push_back(field);
  return extra;
}

}  // namespace hemiroll::game
