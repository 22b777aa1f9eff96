#pragma once
// Joins the parts of one sweep (docs/SWEEP.md, "Sharding"): the complete
// manifests found in the given folders (sweep.json, part-<i>-of-<N>.json),
// all of the same spec (hash) and program version, which together hold
// every point exactly once. The merged CSV is the rows in point order under
// the one header: byte-identical to an unsharded run's, because every row
// is written by the same csvLine from the same fields.

#include <filesystem>
#include <string>
#include <vector>

#include "game/research/sweep/SweepManifest.h"

namespace hemiroll::game {

struct MergedSweep {
  SweepManifest manifest;  // the whole sweep's ("sweep.csv", shard 0/1, complete)
  std::string csv;         // header + every row in point order
  int parts = 0;           // manifests joined
};

// The parts' manifests in a folder, by name (none: an empty list).
std::vector<std::filesystem::path> sweepPartsIn(const std::filesystem::path& dir);

// Throws SweepError with one sentence: bad input when a folder holds no
// parts, a part is incomplete, from another spec or program, or a point is
// missing or given twice; environment when a file cannot be read.
MergedSweep mergeSweepParts(const std::vector<std::filesystem::path>& dirs);

// sweep.csv then sweep.json into dir (created), each atomically.
// Throws SweepError (environment).
void writeMergedSweep(const MergedSweep& merged, const std::filesystem::path& dir);

}  // namespace hemiroll::game
