#pragma once
// Finds where an interrupted session goes on. A trial is done when its
// sidecar says "complete": true AND results.csv has its row (the row is
// appended after the sidecar is completed, so a crash between the two
// leaves a trial that runs again). Done trials must be the first ones of the
// plan; they are kept untouched. Every file of a later trial (the one a
// crash interrupted: its CSV, its sidecar saying "complete": false, a replay
// log) is moved aside, never deleted: <file>.aborted-N with the first N that
// names no file yet for any of the trial's files, so a rerun can record the
// trial afresh under its own name.

#include <filesystem>
#include <vector>

#include "game/research/session/SessionManifest.h"

namespace hemiroll::game {

struct ResumePoint {
  int done = 0;  // trials 1..done are finished
  // Trials after those with files left in the folder, and why they stopped.
  std::vector<std::pair<std::string, std::string>> interrupted;  // trial id, reason
};

// Reads the folder; changes nothing. Throws SessionError (Environment) when
// results.csv cannot be read, lists a trial that is not in the plan or whose
// sidecar is not complete, or when the finished trials are not the plan's
// first ones.
ResumePoint findResumePoint(const std::filesystem::path& folder, const std::vector<ManifestTrial>& plan);

// Renames the trial's files to <file>.aborted-N. Throws SessionError
// (Environment) naming a file that cannot be moved.
ManifestAborted moveTrialAside(const std::filesystem::path& folder, const std::string& trialId,
                               const std::string& reason);

}  // namespace hemiroll::game
