#pragma once
// A sweep spec as canonical JSON: everything that decides the points' rows
// (base parameters, rose, start, duration, step, integrator, tolerance,
// axes with their expanded values), in a fixed key order, numbers in their
// shortest round-trip form. Its hash names the spec in every manifest, so
// parts of one sweep are recognised whatever the file's comments, name or
// description; and `sweep map` rebuilds the axes from it without the file.

#include <string>

#include "engine/task/SweepDef.h"

namespace hemiroll::game {

// Compact JSON text (no description, no source: they decide no row).
std::string specJson(const task::SweepDef& def);
// "fnv1a-<16 hex digits>" of specJson(def).
std::string specHash(const task::SweepDef& def);
// The spec back from specJson's text; throws SweepError (bad input) naming
// `where` when it is not one.
task::SweepDef specFromJson(const std::string& text, const std::string& where);

}  // namespace hemiroll::game
