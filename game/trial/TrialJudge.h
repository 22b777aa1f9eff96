#pragma once
// The one judge of a trial, whoever plays it and on whichever thread the
// servo loop runs (TrialRig owns it: its stepping driver judges each tick's
// snapshot, its threaded one drains the loop's ring of every tick, for `run
// --realtime` and a person in the window). Every tick, in order, none skipped:
//   TaskJudge::judge -> TrialSummaryAccumulator::add -> LevelScript::update
// and a safety fault ends the trial (a bot's), or is left to the caller (a
// human's: the game pauses with the reason and goes on when asked). A rule
// of judging is written here once, so that what a bot is judged by is what
// a player is judged by.
//
// Allocates nothing per tick once warm (the judge and accumulator do not; a
// level's messages are its own).

#include <cstdint>
#include <optional>
#include <string>

#include "engine/haptics/RecordRow.h"
#include "engine/script/LevelLoader.h"
#include "engine/task/TaskJudge.h"
#include "engine/task/TrialSummaryAccumulator.h"

namespace hemiroll::game {

struct TrialResult {
  task::TrialOutcome outcome = task::TrialOutcome::Failure;
  std::string reason;
  double time = 0.0;                 // simulated time at the end [s]
  long long ticks = 0;
  std::optional<double> score;       // nullopt: no score function, or it failed
  task::Medal medal = task::Medal::None;
  std::string scoreError;            // the score function's failure, if any
  std::string endCallbackError;      // on_success / on_fail failed after the end, if so
  task::TrialSummary summary;
  physics::ForceDrivenState finalState = physics::ForceDrivenState::Zero();
  double maxRenderedForce = 0.0;     // largest |force| sent to the device [N]
  double maxProxyDistance = 0.0;     // largest proxy to mass point distance [m]
  double wallTime = 0.0;             // [s]
  // Rows the record tap's full ring refused (TrialRig::tapLost): a recording
  // missing them says so in its sidecar's dropped_rows and results.csv.
  std::uint64_t recordRowsLost = 0;
};

class TrialJudge {
 public:
  // `level` must outlive this.
  explicit TrialJudge(script::LoadedLevel& level, bool faultsEndTrial = true);

  // on_start at the initial state (and on_fail for a trial failed before it).
  void start(const physics::ForceDrivenState& initial);
  // Judges one tick as the loop published it. Ignored once finished.
  void judgeTick(const haptics::ServoSnapshot& tick);
  void judgeTick(const haptics::RecordRow& tick);
  // Ends the trial from outside (bot error, stall, the player quit) at the
  // last judged time; runs on_fail.
  void fail(const std::string& reason);

  task::TaskJudge& judge() { return judge_; }
  const task::TaskJudge& judge() const { return judge_; }
  bool finished() const { return judge_.finished(); }
  const script::TrialObservation& view() const { return view_; }
  long long judgedTicks() const { return judgedTicks_; }
  // The trial summary so far (time, path, effort, margins), for a running score.
  task::TrialSummary summary() const { return accumulator_.summary(judge_); }

  // Outcome, summary, score and medal; `initial` stands for the final state
  // when no tick was judged. wallTime is left to the caller.
  TrialResult result(const physics::ForceDrivenState& initial);

 private:
  template <class Tick>
  void judgeAny(const Tick& tick);

  script::LoadedLevel& level_;
  bool faultsEndTrial_;
  task::TaskJudge judge_;
  task::TrialSummaryAccumulator accumulator_;
  script::TrialObservation view_;
  long long judgedTicks_ = 0;
  double maxRenderedForce_ = 0.0, maxProxyDistance_ = 0.0;
};

}  // namespace hemiroll::game
