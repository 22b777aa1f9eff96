// game/trial/BotTrial in process, stepped headless: the tick loop's contract (determinism,
// bot errors and safety faults as outcomes, forces within the device limit)
// and the rose bot against the paper's prescribed drive.

#include "engine/script/BotScript.h"
#include "game/trial/BotTrial.h"
#include "game/trial/TrialSetup.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "engine/haptics/RecordRow.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/RollingDynamics.h"
#include "engine/physics/RoseDrive.h"
#include "engine/script/LevelLoader.h"
#include "tests/support/TempDirectory.h"

namespace hemiroll::game {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using task::TrialOutcome;

const std::string kBots = std::string(HEMIROLL_SOURCE_DIR) + "/scripts/bots/";

// A level with the paper's set-up and a target far out of reach, so that a
// trial runs until something ends it.
constexpr const char* kOpenLevel = R"lua(
return {
  name = "open field",
  task = { targets = { u_ca = { value = {0.5, 0.5}, tol = 0.004 } }, time_limit = 2 },
}
)lua";

script::LoadedLevel level(const char* source, std::uint64_t seed = 0) {
  script::LevelLoadOptions options;
  options.seed = seed;
  return script::LevelLoader(options).loadSource(source, "level.lua");
}

TrialResult play(const char* levelSource, const std::string& botPath, std::uint64_t seed,
                 TrialSettings settings = {}) {
  script::LoadedLevel l = level(levelSource, seed);
  script::BotLoadOptions options;
  options.seed = seed;
  script::BotScript bot(botPath, options);
  settings.seed = seed;
  return BotTrial(l, bot, settings).run();
}

bool sameBits(const physics::ForceDrivenState& a, const physics::ForceDrivenState& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 12) == 0;
}

TEST(BotTrial, SameSeedSameTrialBitForBit) {
  for (std::uint64_t seed : {1u, 2u}) {
    const TrialResult a = play(kOpenLevel, kBots + "random.lua", seed);
    const TrialResult b = play(kOpenLevel, kBots + "random.lua", seed);
    EXPECT_EQ(a.reason, b.reason);
    EXPECT_EQ(a.ticks, b.ticks);
    EXPECT_EQ(a.time, b.time);
    EXPECT_TRUE(sameBits(a.finalState, b.finalState)) << "seed " << seed;
  }
  const TrialResult one = play(kOpenLevel, kBots + "random.lua", 1);
  const TrialResult six = play(kOpenLevel, kBots + "random.lua", 6);
  EXPECT_FALSE(sameBits(one.finalState, six.finalState)) << "the seed must matter";
}

TEST(BotTrial, ABotErrorEndsTheTrialWithItsPosition) {
  const test::TempDirectory dir;
  const std::string bot = dir.write(
      "late.lua", "return {name = 'late', act = function(t, obs)\n  assert(t < 0.25, 'gave up')\n"
                  "  return obs.mass.x, obs.mass.y, obs.mass.z\nend}");
  const TrialResult r = play(kOpenLevel, bot, 0);
  EXPECT_EQ(r.outcome, TrialOutcome::Failure);
  EXPECT_THAT(r.reason, StartsWith("bot error: "));
  EXPECT_THAT(r.reason, HasSubstr("late.lua:2: gave up"));
  EXPECT_NEAR(r.time, 0.25, 0.0015) << "ends on the tick it fails (1 ms ticks)";
  EXPECT_TRUE(r.finalState.allFinite());
}

TEST(BotTrial, AFailedInitEndsTheTrialAndTheLevelHearsOfIt) {
  // The level's on_fail ends the trial a second way; the first reason stays.
  constexpr const char* kListening = R"lua(
return { name = "listening", task = { targets = { u_ca = { value = {0.5, 0}, tol = 0.004 } }, time_limit = 1 },
  callbacks = { on_fail = function(state, reason) hemiroll.message("heard: " .. reason) end } }
)lua";
  const test::TempDirectory dir;
  const std::string bot = dir.write("bad_init.lua",
                                    "return {name = 'b', init = function(level, seed)\n  error('no level for me')\nend,\n"
                                    "  act = function(t, obs) return 0, 0, 0 end}");
  script::LoadedLevel l = level(kListening);
  script::BotScript b(bot);
  const TrialResult r = BotTrial(l, b, TrialSettings{}).run();
  EXPECT_EQ(r.outcome, TrialOutcome::Failure);
  EXPECT_THAT(r.reason, HasSubstr("bot error: "));
  EXPECT_THAT(r.reason, HasSubstr("bad_init.lua:2: no level for me"));
  EXPECT_EQ(r.ticks, 0);
  const std::vector<script::LevelMessage> messages = l.script->takeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_THAT(messages[0].text, HasSubstr("heard: bot error"));
}

TEST(BotTrial, NanFromABotIsABotErrorNotANanState) {
  const test::TempDirectory dir;
  const std::string bot = dir.write("nan.lua",
                                    "return {name = 'nan', act = function(t, obs)\n"
                                    "  local m = obs.mass\n"
                                    "  return m.x, t > 0.1 and 0 / 0 or m.y, m.z\nend}");
  const TrialResult r = play(kOpenLevel, bot, 0);
  EXPECT_EQ(r.outcome, TrialOutcome::Failure);
  EXPECT_THAT(r.reason, HasSubstr("nan.lua:1: act(t = 0.1"));
  EXPECT_THAT(r.reason, HasSubstr("returned nan as value 2 (y)"));
  EXPECT_TRUE(r.finalState.allFinite());
}

TEST(BotTrial, AJumpTripsTheVelocityGuardAndEndsTheTrial) {
  const test::TempDirectory dir;
  const std::string bot = dir.write("jump.lua",
                                    "return {name = 'jump', act = function(t, obs)\n"
                                    "  local m = obs.mass\n"
                                    "  if t > 0.5 then return m.x + 0.05, m.y, m.z end\n"
                                    "  return m.x, m.y, m.z\nend}");
  const TrialResult r = play(kOpenLevel, bot, 0);
  EXPECT_EQ(r.outcome, TrialOutcome::Failure);
  EXPECT_EQ(r.reason, "safety: device velocity above the guard");
  EXPECT_NEAR(r.time, 0.5, 0.0025);
}

TEST(BotTrial, RenderedForceNeverExceedsTheDeviceLimit) {
  // Adversarial seeds: goals far outside the workspace, teleports, fast moves.
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    const TrialResult r = play(kOpenLevel, kBots + "random.lua", seed);
    EXPECT_LE(r.maxRenderedForce, botDeviceSpec().maxForce) << "seed " << seed;
    EXPECT_TRUE(r.finalState.allFinite()) << "seed " << seed;
    EXPECT_FALSE(r.reason.empty()) << "seed " << seed;
  }
}

// The rose bot plays the paper's Sec. 5 curve through the M3 coupling; the
// prescribed drive (eq. 48) imposes the same curve exactly. Two checks:
//  - the mass point traces the curve p_d(t) on the face (the bot's job);
//  - the coupling's in-face force equals the force of eq. (46), the one the
//    prescribed drive applies to realise p_d'', evaluated at the bot's own
//    state and with the normal load M3 passes through the face: the force
//    that moves the mass point is the drive's, up to the tracking error.
// The two hemisphere trajectories themselves are not compared point by
// point: from the paper's start (body at rest, p(0) off centre) the rigid
// drive rocks the body at ~10 rad/s while the 250 N/m spring filters that
// out, and the motion is chaotic (docs/PHYSICS.md), so they part within
// 0.25 s by design, not by error.
TEST(BotTrial, RoseBotTracesThePrescribedRose) {
  constexpr const char* kRoseLevel = R"lua(
-- p(0) and p'(0) of the curve, as the prescribed drive has them.
return { name = "rose", initial = { x_p = 0.023, yd_p = -math.pi / 10 * (0.015 - 8 * 0.008) },
         task = { time_limit = 6 } }
)lua";
  // The rig's tap, every 10th tick: 600 rows of 6 s fit the ring, read after the trial.
  auto ring = std::make_unique<haptics::RecordRing>();
  script::LoadedLevel l = level(kRoseLevel);
  script::BotScript bot(kBots + "rose.lua", script::BotLoadOptions{});
  BotTrial trial(l, bot, TrialSettings{});
  trial.rig().record({ring.get(), 10});
  const TrialResult r = trial.run();
  std::vector<haptics::RecordRow> rows;
  haptics::RecordRow row;
  while (ring->pop(row)) rows.push_back(row);
  EXPECT_EQ(r.outcome, TrialOutcome::Success) << r.reason;  // watch-only: watched to the end
  ASSERT_GT(rows.size(), 500u);

  // The paper's start is out of balance: in the first ~0.3 s the body tips
  // and the spring takes up the load (the mass point lags by up to 1.4 cm).
  constexpr double kSettled = 0.5;  // [s]
  const physics::RoseDrive rose{physics::RoseDef{}};
  const physics::RollingDynamics dynamics{physics::HemisphereParams{}};
  double worstPoint = 0.0, forceError2 = 0.0, force2 = 0.0;
  for (const haptics::RecordRow& row : rows) {
    if (row.time < kSettled) continue;
    const physics::MassPointTrajectory::Sample want = rose.at(row.time);
    worstPoint = std::max(worstPoint, std::hypot(row.state[0] - want.p.x(), row.state[1] - want.p.y()));
    // Eq. (46) at the bot's own state, with the normal load the M3 coupling
    // puts through the face (the prescribed drive has none), for p_d''.
    physics::ForceDrivenState x;
    for (int i = 0; i < 12; ++i) x[i] = row.state[static_cast<std::size_t>(i)];
    const physics::RollingGeometry g = physics::geometryOf(dynamics.constants(), x);
    const physics::Real3 w = g.frame.toHeading(physics::Real3{x[4], x[5], x[6]});
    const physics::Real3 load = g.frame.toHeading(physics::Real3{row.modelForce[0], row.modelForce[1], row.modelForce[2]});
    const physics::BodyAcceleration acc = dynamics.bodyAcceleration(g, w, physics::dot(g.frame.k, load));
    const physics::Real2 f = dynamics.prescribedForce(g, acc, physics::Real2{want.pDDot.x(), want.pDDot.y()});
    const physics::Real2 coupling = g.frame.toFace(load);
    const double inFaceX = coupling.x, inFaceY = coupling.y;
    forceError2 += (inFaceX - f.x) * (inFaceX - f.x) + (inFaceY - f.y) * (inFaceY - f.y);
    force2 += f.x * f.x + f.y * f.y;
  }
  const double relativeForceError = std::sqrt(forceError2 / force2);
  std::printf("rose bot: worst face-point error %.3g m, RMS in-face force error %.3g of the RMS eq. (46) force\n",
              worstPoint, relativeForceError);
  // 1 mm: a quarter of the paper's 0.4 cm position tolerance; measured 0.52 mm.
  EXPECT_LT(worstPoint, 1e-3);
  // 10%: the in-face force differs from eq. (46) by m_p times the tracking
  // acceleration error (the spring's lag, the one-tick hold); measured 3.4%.
  EXPECT_LT(relativeForceError, 0.1);
}

}  // namespace
}  // namespace hemiroll::game
