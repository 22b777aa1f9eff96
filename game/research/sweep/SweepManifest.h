#pragma once
// The JSON manifest beside each part's CSV (docs/SWEEP.md, "Files"): the
// spec (canonical, with its hash), which shard of how many, the points it
// holds, whether it is complete, and how it was run. Written atomically:
// "complete": false when a run starts, true once the CSV is in place, so a
// manifest that says complete names a CSV that is whole.

#include <filesystem>
#include <string>

#include "game/research/sweep/SweepShard.h"

namespace hemiroll::game {

struct SweepManifest {
  std::string program;          // "hemiroll <version>": parts of different builds are not merged
  std::string specFile;         // as given on the command line (for people; the hash decides)
  std::string description;      // the spec's
  std::string specHash;         // specHash(spec)
  std::string specJson;         // specJson(spec): canonical, compact
  long long pointsTotal = 0;    // the whole grid
  SweepShard shard;
  long long pointCount = 0;     // the shard's points: shard.index + j * shard.count, j < pointCount
  std::string csv;              // the CSV's file name, beside the manifest
  bool complete = false;
  int threads = 0;              // of the run that completed it (0 for a merge)
  double wallSeconds = 0.0;     // that run's wall time [s] (0 for a merge)
  long long resumedPoints = 0;  // rows kept from an interrupted run of the same shard
};

std::string manifestJson(const SweepManifest& m);
// Throws SweepError (bad input) naming `path` when the text is not a sweep
// manifest, or its spec does not match its hash (edited by hand).
SweepManifest parseManifest(const std::string& text, const std::filesystem::path& path);
// Reads and parses the file; SweepError (environment) when it cannot be read.
SweepManifest readManifest(const std::filesystem::path& path);

}  // namespace hemiroll::game
