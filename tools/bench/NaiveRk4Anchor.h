#pragma once
// The anchor of issue 32's sweep measure: a plain 12-state RK4 loop (the
// textbook stages on std::array, the 12-state model's scalar right-hand side
// through its virtual derivative(), free motion), compiled -O2 in its own
// translation unit (tools/CMakeLists.txt). It stands for "one trajectory
// the obvious way": a sweep's trajectory steps per CPU second are quoted as
// a multiple of its steps per CPU second, measured in the same run.

namespace hemiroll::bench {

// Integrates `steps` RK4 steps of 1 ms from a typical playing state; returns
// a component of the end state (so that the work cannot be dropped).
double naiveRk4Anchor(long long steps);

}  // namespace hemiroll::bench
