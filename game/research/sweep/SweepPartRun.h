#pragma once
// Runs one shard of a sweep (or the whole) into an output folder, crash-safe
// (docs/SWEEP.md, "Files" and "Interrupted runs"):
//   <stem>.json          the manifest, "complete": false from the start;
//   <stem>.csv.partial   the rows so far, in point order, one durable append
//                        (write + fdatasync) per point;
//   <stem>.csv           the finished CSV, put in place atomically, then the
//                        manifest rewritten with "complete": true.
// A rerun into the same folder keeps the rows already written (their point
// indices must be the shard's first ones; a cut last line is dropped) and
// computes only the rest, so the CSV is byte-identical to an uninterrupted
// run's. A complete shard is left as it is. A folder holding this shard of
// another spec or program version is refused.

#include <filesystem>
#include <string>

#include "engine/task/SweepDef.h"
#include "game/research/sweep/SweepShard.h"

namespace hemiroll::game {

struct SweepPartRequest {
  task::SweepDef def;
  std::string specFile;            // as given (recorded in the manifest)
  SweepShard shard;
  std::filesystem::path outDir;
  int threads = 1;
  // Trajectories integrated together in SIMD lanes (1: one at a time); the
  // CSV is the same bytes for any width (RoseLockstepRun).
  int laneWidth = 1;
  bool terminal = false;           // draw a progress bar on stderr
  std::string program;             // "hemiroll <version>"
};

struct SweepPartReport {
  long long points = 0;            // the shard's points
  long long resumed = 0;           // rows kept from an interrupted run
  long long computed = 0;          // points run now
  long long stopped = 0;           // rows whose run a domain event stopped (tipped over, left the face)
  double wallSeconds = 0.0;        // this run's
  bool alreadyComplete = false;    // nothing to do: the shard was complete
  std::filesystem::path csv, manifest;
};

// Throws SweepError: bad input (another spec or version in the folder) or
// environment (a file that cannot be written).
SweepPartReport runSweepPart(const SweepPartRequest& request);

}  // namespace hemiroll::game
