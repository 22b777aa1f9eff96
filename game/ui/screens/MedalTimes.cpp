#include "game/ui/screens/MedalTimes.h"

#include <cmath>
#include <cstdio>

namespace hemiroll::game {

namespace {

constexpr int kProbes = 64;  // times across the limit at which the score is asked

}  // namespace

std::optional<MedalTimes> medalTimes(script::LoadedLevel& level) {
  const task::ScoringDef& scoring = level.def.scoring;
  if (!scoring.hasMedals || !scoring.hasScoreFunction || !level.script) return std::nullopt;
  const double limit = level.def.task.timeLimit;
  if (!(limit > 0.0) || !std::isfinite(limit)) return std::nullopt;
  task::TrialSummary success;
  success.outcome = task::TrialOutcome::Success;
  success.reason = "success";
  success.stageCount = static_cast<int>(level.def.task.stages.size());
  success.stagesPassed = success.stageCount;
  success.bestMargin = success.finalMargin = 0.5;
  const auto scoreAt = [&](double t) -> std::optional<double> {
    success.time = t;
    success.ticks = static_cast<long long>(std::llround(t * 1000.0));
    const script::ScoreResult r = level.script->score(success);
    if (!r.score || !std::isfinite(*r.score)) return std::nullopt;
    return r.score;
  };
  // The score must fall with time (never rise), and change.
  double previous = INFINITY, first = 0.0, last = 0.0;
  for (int i = 0; i <= kProbes; ++i) {
    const std::optional<double> s = scoreAt(limit * i / kProbes);
    if (!s || *s > previous) return std::nullopt;
    previous = *s;
    if (i == 0) first = *s;
    last = *s;
  }
  if (!(first > last)) return std::nullopt;
  // The longest time that still scores `threshold` (bisection to 0.01 s).
  const auto timeFor = [&](double threshold) -> double {
    std::optional<double> at0 = scoreAt(0.0);
    if (!at0 || *at0 < threshold) return 0.0;
    double lo = 0.0, hi = limit;
    if (std::optional<double> end = scoreAt(limit); end && *end >= threshold) return limit;
    while (hi - lo > 0.005) {
      const double mid = 0.5 * (lo + hi);
      const std::optional<double> s = scoreAt(mid);
      if (s && *s >= threshold) lo = mid;
      else hi = mid;
    }
    return lo;
  };
  MedalTimes t;
  t.bronze = timeFor(scoring.bronze);
  t.silver = timeFor(scoring.silver);
  t.gold = timeFor(scoring.gold);
  if (!(t.gold > 0.0)) return std::nullopt;  // gold out of reach by any time: not a time score
  return t;
}

std::string medalLine(const task::ScoringDef& scoring, const std::optional<MedalTimes>& times) {
  if (!scoring.hasMedals) return "";
  char line[160];
  if (times)
    std::snprintf(line, sizeof line, "gold in %.3g s, silver %.3g s, bronze %.3g s", times->gold, times->silver,
                  times->bronze);
  else
    std::snprintf(line, sizeof line, "bronze %g, silver %g, gold %g points", scoring.bronze, scoring.silver,
                  scoring.gold);
  return line;
}

}  // namespace hemiroll::game
