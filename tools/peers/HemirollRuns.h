#pragma once
// hemiroll's own runs of the peer scenes: the adaptive reference and the
// methods we put on the same error-cost plot. Owns: building our model for a
// scene and sampling it. Must not know the peers.

#include <string>
#include <vector>

#include "tools/peers/PeerRun.h"

namespace hemiroll::tools::peers {

// The reference the issue names: dop853 in long double at tolerance 1e-12
// (a tighter one checks it).
std::vector<Sample> referenceSamples(const PeerScene& scene, double tolerance = 1e-12);

// One run with a method of IntegratorRegistry: a fixed step h, or for an
// adaptive method a tolerance.
RunResult hemirollRun(const PeerScene& scene, const std::string& integrator, double stepOrTolerance,
                      double targetSeconds, int maxRepeats);

}  // namespace hemiroll::tools::peers
