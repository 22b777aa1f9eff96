#pragma once
// Small sweeps for the sweep's tests: quick to run (12 s of simulated time
// per point, a few points), with a known outcome.

#include <filesystem>
#include <string>

#include "engine/task/SweepDef.h"
#include "game/research/sweep/SweepPartRun.h"

namespace hemiroll::test {

// 3 x 3 (k x Omega) from the static tilt: every run ends without an event.
extern const char* const kTinySweep;
// 2 x 2 (k x Omega) from rest, 3 s: k = 16, Omega = -1 rad/s tips over at
// 0.39 s (point 3); k = 8, Omega = -pi/10 does not (point 0).
extern const char* const kTippingSweep;

task::SweepDef sweepOf(const std::string& source);

// Runs `source` (shard, threads, SIMD lanes) into dir in-process.
game::SweepPartReport runSweepInto(const std::string& source, const std::filesystem::path& dir,
                                   game::SweepShard shard = {}, int threads = 1, int laneWidth = 1);

}  // namespace hemiroll::test
