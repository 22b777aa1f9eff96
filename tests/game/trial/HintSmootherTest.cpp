// game/trial/HintSmoother: the hint is drawn ahead of the hemisphere by its
// lead (c_up's velocity times the lead, a person's delay and one interval),
// never further than its limit, and while the swirl carries the hemisphere
// the ring's centre glides without turning back within a second.

#include "game/trial/HintSmoother.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hemiroll::game {
namespace {

using physics::Vec2;

constexpr double kTick = 0.001;   // [s]
constexpr double kRadius = 0.04;  // [m]

// Upright (c_up is the contact), still, a contact target far off: the
// technique swirls.
script::BotObservation observationAt(double time, const Vec2& contact) {
  script::BotObservation obs;
  obs.time = time;
  obs.engaged = true;
  obs.contact = {contact.x(), contact.y(), 0.0};
  obs.normal = {0.0, 0.0, 1.0};
  obs.targetSet[7] = obs.targetSet[8] = true;
  obs.target[7] = 0.05;
  obs.target[8] = 0.0;
  obs.tolerance[7] = obs.tolerance[8] = 0.001;
  return obs;
}

// The cue's centre (the ring's, or the spot) at each tick of `seconds`
// while the contact follows `path`.
template <typename Path>
std::vector<Vec2> centresShown(const HintSmootherDef& def, double seconds, Path path) {
  HintSmoother smoother(def);
  smoother.reset(kRadius);
  std::vector<Vec2> shown;
  for (int i = 0; i * kTick <= seconds; ++i) {
    const double t = i * kTick;
    const human::HintCue cue = smoother.cue(observationAt(t, path(t)), i == 0 ? 0.0 : kTick, true);
    EXPECT_NE(cue.kind, human::HintKind::None);
    shown.push_back(cue.kind == human::HintKind::Stir ? cue.centre : cue.point);
  }
  return shown;
}

TEST(HintSmoother, TheRingIsDrawnAheadOfTheHemisphereByTheLead) {
  // c_up drifts sideways at 2 mm/s: once the velocity is watched (5 s, ten
  // watch times), the ring stands lead x velocity ahead of where it would
  // stand drawn for now, the same ring otherwise.
  const Vec2 velocity(0.0, 0.002);
  const auto path = [&](double t) { return Vec2(velocity * t); };
  HintSmootherDef now;
  now.lead = 0.0;
  const HintSmootherDef ahead;
  const Vec2 shift = centresShown(ahead, 5.0, path).back() - centresShown(now, 5.0, path).back();
  EXPECT_NEAR(shift.x(), 0.0, 1e-9);
  // 1 mm; the watch converges as exp(-t / leadWatch): exp(-10) of 1 mm is 45 nm.
  EXPECT_NEAR(shift.y(), ahead.lead * velocity.y(), 1e-7);
  EXPECT_GT(ahead.lead, 0.0);
}

TEST(HintSmoother, TheLeadNeverMovesTheRingFurtherThanItsLimit) {
  // c_up racing at 0.1 m/s (a jump, not a hemisphere): lead x velocity
  // would be 5 cm; the ring moves the limit, no further.
  const auto path = [](double t) { return Vec2(0.0, 0.1 * t); };
  HintSmootherDef now;
  now.lead = 0.0;
  const HintSmootherDef ahead;
  const std::vector<Vec2> a = centresShown(ahead, 1.0, path), b = centresShown(now, 1.0, path);
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_LE((a[i] - b[i]).norm(), ahead.leadLimit + 1e-12) << i;
  EXPECT_NEAR((a.back() - b.back()).norm(), ahead.leadLimit, 1e-9);
}

// Whether the centre, at some tick, moved at least `step` over the last
// half second and at least `step` over the next, the two at more than a
// right angle: a turn back within a second.
bool turnsBackWithinASecond(const std::vector<Vec2>& centres, double step) {
  const std::size_t half = static_cast<std::size_t>(0.5 / kTick);
  for (std::size_t i = half; i + half < centres.size(); ++i) {
    const Vec2 before = centres[i] - centres[i - half], after = centres[i + half] - centres[i];
    if (before.norm() >= step && after.norm() >= step && before.dot(after) < 0.0) return true;
  }
  return false;
}

TEST(HintSmoother, WhileTheSwirlCarriesTheHemisphereTheRingNeverTurnsBackWithinASecond) {
  // c_up as the swirl carries it on the paper's task (measured with the
  // human model, seed 1 at a delay of 0.25 s, seconds 10-60: it swings
  // 0.3 mm about its path, at most 0.45 mm in 95 % of the ticks, and
  // drifts about 0.5 mm/s): here a 0.5 mm swing at the swirl's half turn
  // a second over a drift of 0.5 mm/s towards the target.
  const auto path = [](double t) {
    return Vec2(0.0005 * t + 0.0005 * std::cos(M_PI * t), 0.0005 * std::sin(M_PI * t));
  };
  const double step = 0.0005;  // half a millimetre: a turn a person would see and follow
  const std::vector<Vec2> shown = centresShown(HintSmootherDef{}, 20.0, path);
  EXPECT_FALSE(turnsBackWithinASecond(std::vector<Vec2>(shown.begin() + 2000, shown.end()), step));
  // The check sees a turn back where there is one: drawn three seconds
  // ahead, the swing's velocity circles the ring 1.5 mm about its path.
  HintSmootherDef far;
  far.lead = 3.0;
  const std::vector<Vec2> wobbling = centresShown(far, 20.0, path);
  EXPECT_TRUE(turnsBackWithinASecond(std::vector<Vec2>(wobbling.begin() + 2000, wobbling.end()), step));
}

TEST(HintSmoother, NoHintWithoutAPlanNorOnAStageWithoutAContactTarget) {
  HintSmoother smoother;
  smoother.reset(kRadius);
  EXPECT_EQ(smoother.cue(observationAt(0.0, Vec2::Zero()), 0.0, false).kind, human::HintKind::None);
  script::BotObservation lean = observationAt(0.001, Vec2::Zero());
  lean.targetSet[7] = lean.targetSet[8] = false;
  EXPECT_EQ(smoother.cue(lean, kTick, true).kind, human::HintKind::None);
  EXPECT_EQ(smoother.cue(observationAt(0.002, Vec2::Zero()), kTick, true).kind, human::HintKind::Stir);
}

}  // namespace
}  // namespace hemiroll::game
