#pragma once
// session.json: what a research session is, written when it starts and
// rewritten (atomically) when it resumes or moves an interrupted trial's
// files aside. Keys and units: docs/PROTOCOLS.md, "The session folder".
// It records the protocol file and its content hash (a resumed session must
// run the same protocol), the participant, the session id, the seed, the
// expanded plan with each trial's level hash and effective coupling, the
// start time and program version of every sitting, and every interrupted
// trial whose files were moved aside.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/haptics/Guidance.h"

namespace hemiroll::game {

struct ManifestBreak {
  std::string message;
  double minDuration = 0.0;  // [s]
  bool stop = false;
};

// One trial of the plan with everything the session decided for it.
struct ManifestTrial {
  int index = 0;               // 1-based
  std::string trialId;         // "trial-001": its files' names
  int block = 0;               // 1-based
  std::string blockName;
  int trialInBlock = 0;
  int repetition = 0;
  int condition = 0;
  std::string conditionLabel;
  std::string levelFile;       // as found (relative to the working directory, or absolute)
  std::string levelName;
  std::string levelHash;       // record::fileContentHash of the file when the session started
  std::string method;          // the effective coupling: "M1", "M2", "M3", "visual"
  double stiffness = 0.0;      // kr [N/m]
  double damping = 0.0;        // kv [N s/m]
  double alpha = 0.0;          // [-]
  double timeLimit = 0.0;      // [s]
  std::uint64_t seed = 0;      // the level's and the bot's
  haptics::GuidanceDef guidance;  // the trial's haptic guidance, its scale the fade value of this trial
  std::optional<ManifestBreak> breakBefore;
};

// One run of the session (the first, and each resume).
struct ManifestSitting {
  std::string startTime;       // ISO-8601 UTC
  std::string softwareVersion;
  int firstTrial = 0;          // the first trial this sitting ran (1-based)
  std::string player;          // "mouse" or the bot file
};

struct ManifestAborted {
  std::string trialId;
  std::string time;            // when the files were moved aside
  std::string reason;
  std::vector<std::pair<std::string, std::string>> moved;  // file -> new name (in the folder)
};

struct SessionManifest {
  std::string experiment, description;
  std::string protocolFile, protocolHash, protocolVersion;
  std::string participant, session;
  // Between-subjects design (PROTOCOLS.md "Groups and counterbalancing"):
  // "" and 1 when the protocol has none. Manifests written before groups
  // have none.
  std::string group;
  int blockOrder = 1;                 // 1-based row of the protocol's block orders
  std::string assignedBy;             // where the group came from, in words
  std::vector<std::pair<std::string, std::string>> participantInfo;  // the participants file's own columns
  std::uint64_t seed = 0;
  std::string startTime, softwareVersion;
  std::vector<ManifestSitting> sittings;
  std::vector<ManifestTrial> plan;
  std::vector<ManifestAborted> aborted;

  std::string toJson() const;
  // Throws std::runtime_error naming `source` and what is wrong.
  static SessionManifest fromJson(const std::string& text, const std::string& source);
};

}  // namespace hemiroll::game
