#pragma once
// How a trial runs, as the scripts and policies that play in it need to
// know it to keep within their budgets (issue 33): headless, as fast as the
// CPU allows, a trial's computation is bounded by a multiple of its
// simulated time; in real time every tick has a deadline, and what a tick
// runs must fit it.

namespace hemiroll::script {

struct TrialTiming {
  bool realtime = false;
  // Real time: the deadline of one call a tick makes (the bot's period:
  // 2 ms at 500 Hz) [s]. Unused headless.
  double tickSeconds = 0.002;
};

}  // namespace hemiroll::script
