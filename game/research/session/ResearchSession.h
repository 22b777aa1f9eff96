#pragma once
// A research session: a protocol (docs/PROTOCOLS.md) run for one
// participant into its folder (SessionFolder.h), trial after trial, by a bot
// (`hemiroll session --bot`) or a person (the game's research screen). Both
// drive it the same way:
//
//   ResearchSession s(request);          // load, plan, check; changes nothing
//   s.begin("mouse");                    // folder, manifest, interrupted files aside
//   while (!s.complete() && !s.stopsHere()) {
//     ... s.pendingBreak(), s.nextTrial() ...
//     LoadedLevel level = s.loadNextLevel();       // with the plan's overrides
//     ... the trial's rig (BotTrial, PlaySession) ...
//     auto recording = s.recordNext(level.def, rig.loopDef(), "mouse", spec);
//     rig.record(recording->tap()); ... play the trial ...
//     s.finishNext(*recording, result);            // sidecar complete + results row
//   }
//
// A session folder with a manifest is resumed: the protocol file must have
// the same content (hash) and seed, and every level the same content, or the
// session is refused (start a new session id instead).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/haptics/ServoLoop.h"
#include "engine/script/LevelLoader.h"
#include "engine/task/DeviceProfileDef.h"
#include "engine/task/ProtocolDef.h"
#include "game/trial/TrialRecording.h"
#include "game/research/session/SessionError.h"
#include "game/research/session/SessionLock.h"
#include "game/research/session/SessionManifest.h"

namespace hemiroll::game {

// A condition's guidance for the block's trial `trialInBlock` (1-based):
// the protocol's spec with the fade value of that trial as its scale.
haptics::GuidanceDef guidanceOf(const task::TrialOverrides& overrides, int trialInBlock);

struct SessionRequest {
  std::string protocolPath;
  std::string levelsDir;                  // "" = the protocol loader's default (ProtocolLoadOptions)
  std::string participant;
  std::string session = "1";
  std::filesystem::path dataRoot;         // "" = defaultSessionsRoot()
  std::optional<std::uint64_t> seed;      // none = the session's (resumed) or the protocol's
  // --device-profile: the device's profile (DeviceProfiles.h); none = the
  // protocol's `device_profile`, if any. Naming another than the protocol's is refused.
  std::optional<std::string> deviceProfile;
  // What the protocol and its levels are loaded with (the window's screens
  // give a listing's shorter limits; game/ui/screens/ListingBudget.h).
  script::SandboxLimits loadLimits;
};

class ResearchSession {
 public:
  // Loads the protocol and every level it names, expands the plan, and, when
  // the session folder has a manifest, checks it and finds where to go on.
  // Writes nothing. Throws SessionError.
  explicit ResearchSession(const SessionRequest& request);

  // Starts (or resumes) the sitting: creates the folder, takes its lock
  // (SessionLock.h: held until this object is destroyed; another session
  // running in the folder is refused), moves the files of an interrupted
  // trial aside and (re)writes the manifest with this sitting (`player`:
  // "mouse" or the bot file). Throws SessionError (Environment), also when
  // the folder changed between the constructor and now (another session
  // ran in it meanwhile).
  void begin(const std::string& player);
  // "" or the note of a stale lock taken over by begin().
  const std::string& lockNote() const;

  const task::ProtocolDef& protocol() const { return protocol_; }
  // The device profile the session runs on (the request's or the protocol's); none when neither names one.
  const std::optional<task::DeviceProfileDef>& deviceProfile() const { return profile_; }
  const SessionManifest& manifest() const { return manifest_; }
  const std::filesystem::path& folder() const { return folder_; }
  int trialCount() const { return static_cast<int>(manifest_.plan.size()); }
  int done() const { return done_; }
  int keptFromEarlier() const { return kept_; }       // finished before this sitting
  bool resumed() const { return resumed_; }           // the folder had a manifest
  bool complete() const { return done_ == trialCount(); }
  // Trials with files left by a crash (moved aside by begin()).
  const std::vector<std::pair<std::string, std::string>>& interrupted() const { return interrupted_; }
  const ManifestTrial& nextTrial() const { return manifest_.plan.at(static_cast<std::size_t>(done_)); }
  const std::string& instructionsOf(const ManifestTrial& trial) const;
  // The break before the next trial (nullptr: none); stopsHere(): it ends
  // the sitting (a stop break reached after a trial of this sitting; a
  // sitting that starts at it just shows it).
  const ManifestBreak* pendingBreak() const;
  bool stopsHere() const;

  // "" when every trial still to run has a coupling `device` renders
  // stably; else one sentence naming the first that has not (a protocol's
  // kr, alpha too stiff for the device): checked before the first trial.
  // With a device profile, the sentence names the level and the profile.
  std::string couplingProblem(const haptics::DeviceSpec& device) const;

  // The next trial's level with the plan's overrides and seed. Throws
  // SessionError (BadInput) when it no longer loads.
  script::LoadedLevel loadNextLevel() const;
  // Opens the next trial's recording. Throws SessionError (Environment).
  std::unique_ptr<TrialRecording> recordNext(const task::LevelDef& level, const haptics::ServoLoopDef& loop,
                                             const std::string& deviceName, const haptics::DeviceSpec& spec) const;
  // Completes the sidecar, appends the results row and moves on. Throws
  // SessionError (Environment).
  // `device`: results.csv's device columns (deviceResultFields; a bot's when
  // none given); `outcome`: the sidecar's outcome.device.
  void finishNext(TrialRecording& recording, const TrialResult& result,
                  const std::optional<haptics::LoopTimingSummary>& timing = std::nullopt,
                  const record::Fields& device = {}, const record::Fields& outcome = {});

 private:
  // The extra columns of `t`'s row in results.csv (their names never depend
  // on the result, so they can be checked before the trial).
  record::Fields resultsFields(const ManifestTrial& t, const TrialResult& result, const record::Fields& device) const;
  void buildPlan(const SessionRequest& request, std::uint64_t seed);
  void checkAgainst(const SessionManifest& previous) const;
  // The resumed session's group and order (checked against the participants file).
  void keepAssignment(const SessionManifest& previous);
  // Refuses a results.csv whose header is not this version's (a session
  // begun by a version that wrote other columns), saying why and what to do.
  void checkResultsColumns(const SessionManifest& previous) const;

  task::ProtocolDef protocol_;
  std::optional<task::DeviceProfileDef> profile_;
  SessionManifest manifest_;
  std::filesystem::path folder_;
  std::string player_;
  int done_ = 0, kept_ = 0, ranThisSitting_ = 0;
  bool resumed_ = false;
  std::vector<std::pair<std::string, std::string>> interrupted_;
  // Per planned trial: the level file as found now and the protocol's overrides.
  std::vector<std::pair<std::string, task::TrialOverrides>> trials_;
  std::vector<int> definedBlocks_;  // per planned trial: its block in the protocol file (1-based)
  std::unique_ptr<SessionLock> lock_;
};

}  // namespace hemiroll::game
