#pragma once
// What a sweep part's manifest says about the arithmetic that made it, so
// that merge and resume refuse parts whose bytes could differ: a short run of
// the sweep's own path (the rose drive from rest, chaotic, through
// measurePoint and sweepRow) with each of the integrators a spec is likely to
// name, hashed. The same binary on another machine may link another C
// library, whose sin and cos (the rose drive's, the analysis') can differ in
// the last bit; a new build may change the physics. Either changes the
// fingerprint (from rest, a one-ulp difference grows to the whole state in
// seconds); equal fingerprints on different machines are the evidence that
// their parts can be merged. Computed once per process, in a few ms.

#include <string>

#include "engine/task/SweepDef.h"

namespace hemiroll::game {

// "fnv1a-<16 hex digits>" for this process.
const std::string& physicsFingerprint();

// The same for a given base spec (its params, rose and tolerance; the start,
// duration, integrator and axes are the fingerprint's own): the test's
// handle on what the fingerprint sees.
std::string physicsFingerprintOf(const task::SweepDef& base);

}  // namespace hemiroll::game
