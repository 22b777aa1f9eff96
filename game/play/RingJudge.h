#pragma once
// The main-thread half of a real-time trial, shared by `hemiroll run
// --realtime` (RealtimeTrial, a bot) and the game's play session (a human
// with the mouse): every tick the servo loop pushed into its record ring is
// judged here, in order, none skipped -
//   TaskJudge::judge -> TrialSummaryAccumulator::add -> LevelScript::update
// - and a safety fault ends the trial (a bot's), or is left to the caller
// (a human's: the game pauses with the reason and goes on when asked). The servo thread never waits for this:
// a ring that fills up is the loop's recordDropped(), which the caller turns
// into a failure.
//
// Allocates nothing per tick once warm (the judge and accumulator do not; a
// level's messages are its own).

#include "engine/haptics/RecordRow.h"
#include "engine/script/LevelLoader.h"
#include "engine/script/TaskJudge.h"
#include "engine/script/TrialSummaryAccumulator.h"
#include "game/play/HeadlessTrial.h"

namespace hemiroll::game {

class RingJudge {
 public:
  // `level` must outlive this; `forward` (may be null) receives every
  // `forwardEvery`-th row (a recording's ring).
  RingJudge(script::LoadedLevel& level, haptics::RecordRing* forward = nullptr, int forwardEvery = 10,
            bool faultsEndTrial = true);

  // on_start at the initial state.
  void start(const physics::ForceDrivenState& initial);
  // Judges every row the ring holds now; returns the number judged.
  std::size_t drain(haptics::RecordRing& ring);
  // Ends the trial from outside (bot error, stall, the player quit); runs on_fail.
  void fail(const std::string& reason);

  script::TaskJudge& judge() { return judge_; }
  const script::TaskJudge& judge() const { return judge_; }
  bool finished() const { return judge_.finished(); }
  const script::TrialObservation& view() const { return view_; }
  long long judgedTicks() const { return judgedTicks_; }
  // The trial summary so far (time, path, effort, margins), for a running score.
  script::TrialSummary summary() const { return accumulator_.summary(judge_); }

  // Outcome, summary, score and medal; `initial` stands for the final state
  // when no tick was judged. wallTime is left to the caller.
  TrialResult result(const physics::ForceDrivenState& initial);

 private:
  script::LoadedLevel& level_;
  haptics::RecordRing* forward_;
  int forwardEvery_;
  bool faultsEndTrial_;
  script::TaskJudge judge_;
  script::TrialSummaryAccumulator accumulator_;
  script::TrialObservation view_;
  long long judgedTicks_ = 0;
  double maxRenderedForce_ = 0.0, maxProxyDistance_ = 0.0;
};

}  // namespace hemiroll::game
