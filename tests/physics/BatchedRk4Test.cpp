// BatchedRk4.h: every lane, at every width this CPU runs, has exactly the
// bits of the scalar path (RungeKutta4 on PrescribedDriveSystem with a
// RoseDrive, or on ForceDrivenSystem free or coupled to a held proxy); a
// retired lane stops while the others go on; widths this CPU lacks and a
// mixed coupling are refused.
//
// Why exact equality, not a tolerance: the lanes run the scalar systems' own
// arithmetic (the templates of RollingDynamics.h and the systems' rates
// functions), so any difference is a bug, and sweeps rely on the bits.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <cstdlib>
#include <limits>
#include <deque>
#include <optional>
#include <random>
#include <vector>

#include "engine/physics/BatchedRk4.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/Integrator.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "engine/physics/RoseDrive.h"
#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {
namespace {

using physics::BodyState;
using physics::CouplingDef;
using physics::ForceDrivenState;
using physics::ForceMethod;
using physics::ProxyPose;
using physics::RoseDef;

std::vector<int> supportedWidths() {
  std::vector<int> widths;
  for (int w : {1, 2, 4, 8})
    if (physics::laneWidthSupported(w)) widths.push_back(w);
  return widths;
}

template <int N>
bool sameBits(const physics::StateVector<N>& a, const physics::StateVector<N>& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * N) == 0;
}

// Eleven lanes: not a multiple of any width, so padding lanes are stepped too.
constexpr int kLanes = 11;

struct RoseLane {
  HemisphereParams params;
  RoseDef rose;
  BodyState x0;
};

// Varied masses, roses and starts. Some tilts exceed 0.78 rad and some psi
// are large, so sinCosLanes reduces the angle; one lane's psi is beyond the
// exact reduction range, so that group takes the per-lane fallback.
std::vector<RoseLane> roseLanes() {
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<RoseLane> lanes;
  for (int i = 0; i < kLanes; ++i) {
    RoseLane l;
    l.params.pointMass = 1.0 + 0.3 * unit(rng);
    l.params.shellMass = 0.1 + 0.05 * unit(rng);
    l.params.radius = 0.04 + 0.01 * unit(rng);
    l.rose.k = 4.0 + i;
    l.rose.omega = -0.04 - 0.09 * i;
    l.rose.r1 = 0.015 + 0.002 * unit(rng);
    l.rose.r2 = 0.008 + 0.002 * unit(rng);
    for (int s = 0; s < 8; ++s) l.x0[s] = 0.3 * unit(rng);
    l.x0[physics::body_slot::u_o] = (i % 3 == 0 ? 1.1 : 0.2) * unit(rng);
    l.x0[physics::body_slot::psi] = i == 5 ? 2.0e6 : (i % 2 == 0 ? 40.0 * unit(rng) : unit(rng));
    lanes.push_back(l);
  }
  return lanes;
}

// Runs every lane through the batch at `width` and through the scalar path,
// retiring lane `retireLane` after `retireAfter` steps; expects the same bits
// at every step.
void expectRoseLanesMatchScalar(int width, int steps, int retireLane, int retireAfter) {
  const std::vector<RoseLane> lanes = roseLanes();
  physics::RoseBatch batch(width);
  std::vector<physics::RoseDrive> roses;
  roses.reserve(lanes.size());
  std::vector<physics::PrescribedDriveSystem> systems;
  systems.reserve(lanes.size());
  std::vector<BodyState> scalar;
  for (const RoseLane& l : lanes) {
    EXPECT_EQ(batch.add(l.params, l.rose, l.x0), static_cast<int>(scalar.size()));
    roses.emplace_back(l.rose);
    systems.emplace_back(l.params, roses.back());
    scalar.push_back(l.x0);
  }
  for (int lane = 0; lane < kLanes; ++lane)  // before any step: the start
    ASSERT_TRUE(sameBits<8>(batch.previousState(lane), scalar[lane])) << "lane " << lane;
  physics::RungeKutta4<8> rk4;
  const double h = 1e-3;
  int gridEndsOffTheStep = 0;
  for (int i = 0; i < steps; ++i) {
    if (i == retireAfter) batch.retire(retireLane);
    const double t = static_cast<double>(i) * h;
    // The grid end as a run's clock gives it, i h, which is not always t + h.
    const double gridEnd = static_cast<double>(i + 1) * h;
    gridEndsOffTheStep += gridEnd != t + h;
    batch.step(t, h, gridEnd);
    for (int lane = 0; lane < kLanes; ++lane) {
      ASSERT_TRUE(sameBits<8>(batch.previousState(lane), scalar[lane])) << "lane " << lane << ", step " << i;
      if (lane != retireLane || i < retireAfter) rk4.step(systems[lane], t, scalar[lane], h);
      ASSERT_TRUE(sameBits<8>(batch.state(lane), scalar[lane]))
          << "width " << width << ", lane " << lane << ", step " << i << ": " << batch.state(lane).transpose()
          << " vs " << scalar[lane].transpose();
      // The drive's position the lanes keep for the domain check is the
      // scalar rose's at the step's end, for every lane that stepped.
      if (!batch.active(lane)) continue;
      const physics::Vec2 p = roses[lane].at(t + h).p;
      ASSERT_EQ(batch.drivePosition(lane).x(), p.x()) << "width " << width << ", lane " << lane << ", step " << i;
      ASSERT_EQ(batch.drivePosition(lane).y(), p.y()) << "width " << width << ", lane " << lane << ", step " << i;
      const physics::Vec2 q = roses[lane].at(gridEnd).p;
      ASSERT_EQ(batch.gridDrivePosition(lane).x(), q.x()) << "width " << width << ", lane " << lane << ", step " << i;
      ASSERT_EQ(batch.gridDrivePosition(lane).y(), q.y()) << "width " << width << ", lane " << lane << ", step " << i;
    }
  }
  EXPECT_EQ(batch.activeCount(), kLanes - 1);
  EXPECT_FALSE(batch.active(retireLane));
  EXPECT_GT(gridEndsOffTheStep, 0) << "the rose at a grid end other than t + h was not tried";
}

TEST(BatchedRk4Test, RoseLanesHaveTheScalarBitsAtEveryWidth) {
  for (int width : supportedWidths()) expectRoseLanesMatchScalar(width, 300, 3, 120);
}

// The lanes keep the rose's sample at a step's grid end and reuse it when
// the next step begins at that time to the bit. A clock that does not go on
// from there (a step taken again from an earlier time, a step from t + h
// where the grid end was not t + h), and lanes added beside ones already
// stepped (the kept sample is of other roses), must each sample the rose
// anew: every lane keeps the scalar bits throughout. (The steps at -0.0 and
// of length 0 only check that those clocks keep the bits too: a rose at
// -0.0 differs from one at +0.0 only in the sign of a zero in p', which the
// state does not show, so they cannot tell == from the kernel's bit test.)
void expectRoseLanesMatchScalarOnAnIrregularClock(int width) {
  const std::vector<RoseLane> lanes = roseLanes();
  physics::RoseBatch batch(width);
  std::deque<physics::RoseDrive> roses;
  std::deque<physics::PrescribedDriveSystem> systems;
  std::vector<BodyState> scalar;
  auto addLanes = [&](int count) {
    for (int i = 0; i < count; ++i) {
      const RoseLane& l = lanes[scalar.size()];
      batch.add(l.params, l.rose, l.x0);
      roses.emplace_back(l.rose);
      systems.emplace_back(l.params, roses.back());
      scalar.push_back(l.x0);
    }
  };
  physics::RungeKutta4<8> rk4;
  const double h = 1e-3;
  int step = 0;
  auto stepAll = [&](double t, double stepSize, double gridEnd, const char* what) {
    batch.step(t, stepSize, gridEnd);
    for (std::size_t lane = 0; lane < scalar.size(); ++lane) {
      rk4.step(systems[lane], t, scalar[lane], stepSize);
      ASSERT_TRUE(sameBits<8>(batch.state(static_cast<int>(lane)), scalar[lane]))
          << "width " << width << ", lane " << lane << ", step " << step << " (" << what << ")";
      const physics::Vec2 q = roses[lane].at(gridEnd).p;
      ASSERT_EQ(batch.gridDrivePosition(static_cast<int>(lane)).x(), q.x()) << "width " << width << ", " << what;
      ASSERT_EQ(batch.gridDrivePosition(static_cast<int>(lane)).y(), q.y()) << "width " << width << ", " << what;
    }
    ++step;
  };
  // Three lanes; five more into the groups already stepped (eight lanes lay
  // out as before at every width); the rest into new groups.
  addLanes(3);
  for (int i = 0; i < 10; ++i) stepAll(i * h, h, (i + 1) * h, "on the grid");
  addLanes(5);
  for (int i = 10; i < 15; ++i) stepAll(i * h, h, (i + 1) * h, "after lanes joined stepped groups");
  addLanes(kLanes - 8);
  for (int i = 15; i < 20; ++i) stepAll(i * h, h, (i + 1) * h, "after lanes were added in new groups");
  stepAll(5 * h, h, 6 * h, "taken again from an earlier time");
  // A grid end off t + h, and the next step from t + h instead.
  int off = 1;
  while (static_cast<double>(off + 1) * h == static_cast<double>(off) * h + h) ++off;
  const double t = static_cast<double>(off) * h;
  ASSERT_NE(t + h, static_cast<double>(off + 1) * h);
  stepAll(t, h, static_cast<double>(off + 1) * h, "a grid end off t + h");
  stepAll(t + h, h, t + 2 * h, "from t + h, not from the grid end");
  stepAll(-h, h, 0.0, "ending at +0.0");
  stepAll(-0.0, h, h, "from -0.0");
  stepAll(h, 0.0, h, "a step of length 0");
}

TEST(BatchedRk4Test, TheRoseIsReusedOnlyAtItsOwnTimeAndRoses) {
  for (int width : supportedWidths()) expectRoseLanesMatchScalarOnAnIrregularClock(width);
}

// The lanes' domain check (RoseBatch::surelyInside) must answer exactly as
// the scalar fast path does on the same state and rose positions:
// InteriorCheck::surelyInside at t + h and at the grid end, and allFinite.
// A step of length 0 leaves each state as set (x + 0 k), so states can be
// put on the edges: the tilt sum and |p|^2 within a few ulp of each lane's
// bounds (the check's own bounds moved to straddle p), NaN and infinities
// in any slot, and far inside or outside. Each round is a new batch: lanes
// near the edges, or all but one far inside, or all far inside (so that
// everyActiveLaneSurelyInside is seen both ways), with a lane retired
// (whose verdict must not count).
void expectLaneDomainCheckIsTheScalars(int width) {
  std::mt19937_64 rng(20261127 + width);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto ulps = [&](double x, int most) {  // x moved by up to `most` ulp either way
    const int n = static_cast<int>(rng() % (2 * most + 1)) - most;
    for (int i = 0; i < std::abs(n); ++i) x = std::nextafter(x, n > 0 ? 1e300 : -1e300);
    return x;
  };
  const double special[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity()};
  int verdicts[2] = {0, 0}, edgeVerdicts[2] = {0, 0}, wholeVerdicts[2] = {0, 0}, nonFinite = 0;
  const std::vector<RoseLane> lanes = roseLanes();
  for (int round = 0; round < 400; ++round) {
    const int mode = round % 3;  // 0: near the edges, 1: all far inside but one, 2: all far inside
    const double t = 100.0 * unit(rng);
    const double gridEnd = rng() % 2 ? t : ulps(t, 2);  // the grid end at t, or off it in the last bits
    physics::RoseBatch batch(width);
    std::vector<physics::InteriorCheck> checks;
    std::vector<bool> nearEdge;
    for (int lane = 0; lane < kLanes; ++lane) {
      const RoseLane& l = lanes[lane];
      const physics::RoseDrive rose(l.rose);
      const physics::Vec2 p = rose.at(rng() % 2 ? t : gridEnd).p;  // straddle at one of the two times
      const bool edge = mode == 0 || (mode == 1 && lane == round % kLanes);
      const double cosMaxTilt = std::cos(0.3 + 1.2 * unit(rng));
      // faceBoundSquared is faceLimit^2 (1 - 1e-6): put it within ulp of |p|^2.
      const double faceLimit = edge && rng() % 2 ? ulps(std::sqrt(p.squaredNorm() / (1.0 - 1e-6)), 3) : 1.0;
      checks.emplace_back(cosMaxTilt, faceLimit);
      BodyState x;
      for (int s = 0; s < 8; ++s) x[s] = 0.05 * (2.0 * unit(rng) - 1.0);
      const double tiltSum = edge && rng() % 2 ? ulps(checks.back().tiltSumBound(), 3)
                             : edge           ? checks.back().tiltSumBound() * (0.5 + unit(rng))
                                              : 0.1 * unit(rng);
      const double split = rng() % 4 == 0 ? 0.0 : unit(rng);
      x[physics::body_slot::u_o] = (rng() % 2 ? 1.0 : -1.0) * split * tiltSum;
      x[physics::body_slot::v_o] = (rng() % 2 ? 1.0 : -1.0) * (1.0 - split) * tiltSum;
      if (edge && rng() % 4 == 0) x[static_cast<int>(rng() % 8)] = special[rng() % 3];
      nearEdge.push_back(edge);
      batch.add(l.params, l.rose, x, checks.back());
    }
    // Retiring the one lane near the edges leaves every active lane inside.
    const int retired = static_cast<int>(mode == 1 && rng() % 2 ? round % kLanes : rng() % kLanes);
    batch.retire(retired);
    batch.step(t, 0.0, gridEnd);
    bool every = true;
    for (int lane = 0; lane < kLanes; ++lane) {
      if (!batch.active(lane)) continue;
      const BodyState x = batch.state(lane);
      const physics::Vec2 end = batch.drivePosition(lane), grid = batch.gridDrivePosition(lane);
      const physics::InteriorCheck& c = checks[lane];
      using physics::body_slot::u_o, physics::body_slot::v_o;
      const bool scalar = c.surelyInside(x[u_o], x[v_o], end.x(), end.y()) && x.allFinite() &&
                          c.surelyInside(x[u_o], x[v_o], grid.x(), grid.y());
      ASSERT_EQ(batch.surelyInside(lane), scalar)
          << "width " << width << ", round " << round << ", lane " << lane << ": " << x.transpose();
      every = every && scalar;
      ++verdicts[scalar];
      if (nearEdge[lane]) ++edgeVerdicts[scalar];
      nonFinite += !x.allFinite();
    }
    ASSERT_EQ(batch.everyActiveLaneSurelyInside(), every) << "width " << width << ", round " << round;
    ++wholeVerdicts[every];
  }
  // The draws reached both answers, on the edges too, and non-finite states.
  EXPECT_GT(edgeVerdicts[0], 200) << "width " << width;
  EXPECT_GT(edgeVerdicts[1], 200) << "width " << width;
  EXPECT_GT(wholeVerdicts[0], 100) << "width " << width;
  EXPECT_GT(wholeVerdicts[1], 100) << "width " << width;
  EXPECT_GT(nonFinite, 50) << "width " << width;
  EXPECT_GT(verdicts[1], verdicts[0]) << "width " << width;
}

TEST(BatchedRk4Test, TheLanesDomainCheckIsTheScalarFastPath) {
  for (int width : supportedWidths()) expectLaneDomainCheckIsTheScalars(width);
}

// A lane added without its system's InteriorCheck is never surely inside:
// its caller checks it exactly.
TEST(BatchedRk4Test, ALaneWithoutAnInteriorCheckIsNeverSurelyInside) {
  for (int width : supportedWidths()) {
    physics::RoseBatch batch(width);
    const RoseLane l = roseLanes()[1];
    BodyState upright = BodyState::Zero();
    batch.add(l.params, l.rose, upright);
    batch.step(0.0, 1e-3);
    EXPECT_FALSE(batch.surelyInside(0)) << "width " << width;
    EXPECT_FALSE(batch.everyActiveLaneSurelyInside()) << "width " << width;
    // The same lane with its system's check passes.
    physics::RoseBatch checked(width);
    const physics::RoseDrive rose(l.rose);
    const physics::PrescribedDriveSystem system(l.params, rose);
    checked.add(l.params, l.rose, upright, system.interior());
    checked.step(0.0, 1e-3);
    EXPECT_TRUE(checked.surelyInside(0)) << "width " << width;
    EXPECT_TRUE(checked.everyActiveLaneSurelyInside()) << "width " << width;
  }
}

TEST(BatchedRk4Test, TheBestWidthIsOneThisCpuRuns) {
  const int best = physics::bestLaneWidth();
  EXPECT_TRUE(best == 2 || best == 4 || best == 8);
  EXPECT_TRUE(physics::laneWidthSupported(best));
  EXPECT_FALSE(physics::laneWidthSupported(3));
  EXPECT_FALSE(physics::laneWidthSupported(16));
}

TEST(BatchedRk4Test, AWidthThisCpuLacksIsRefusedByName) {
  try {
    physics::RoseBatch batch(3);
    FAIL() << "width 3 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lane width 3"), std::string::npos) << e.what();
  }
}

// The 12-state lanes: free, or coupled by M1, M2 or M3 with per-lane gains
// and proxies that move every few steps, as the servo holds them.
void expectForceDrivenLanesMatchScalar(int width, std::optional<ForceMethod> method) {
  std::mt19937 rng(7 + (method ? static_cast<int>(*method) : 9));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  physics::ForceDrivenBatch batch(method, width);
  std::vector<std::unique_ptr<physics::ForceDrivenSystem>> systems;
  std::vector<ForceDrivenState> scalar;
  for (int lane = 0; lane < kLanes; ++lane) {
    HemisphereParams params;
    params.pointMass = 1.0 + 0.4 * unit(rng);
    params.shellMass = 0.1 + 0.05 * unit(rng);
    CouplingDef coupling;
    coupling.method = method.value_or(ForceMethod::M3);
    coupling.stiffness = 250.0 + 100.0 * unit(rng);
    coupling.damping = 10.0 + 5.0 * unit(rng);
    coupling.alpha = 2.5 + 1.5 * unit(rng);
    ForceDrivenState x0;
    for (int s = 0; s < 12; ++s) x0[s] = 0.2 * unit(rng);
    x0[physics::force_slot::x_p] = 0.01 * unit(rng);
    x0[physics::force_slot::y_p] = 0.01 * unit(rng);
    x0[physics::force_slot::v_o] = (lane % 4 == 1 ? 0.9 : 0.1) * unit(rng);
    batch.add(params, coupling, x0);
    systems.push_back(std::make_unique<physics::ForceDrivenSystem>(params));
    if (method) systems.back()->setCoupling(coupling);
    scalar.push_back(x0);
  }
  physics::RungeKutta4<12> rk4;
  const double h = 1e-3;
  for (int i = 0; i < 200; ++i) {
    if (method && i % 10 == 0) {
      for (int lane = 0; lane < kLanes; ++lane) {
        ProxyPose pose;
        pose.position = Vec3(0.02 * unit(rng), 0.02 * unit(rng), 0.04 + 0.01 * unit(rng));
        pose.velocity = Vec3(0.1 * unit(rng), 0.1 * unit(rng), 0.02 * unit(rng));
        batch.holdProxy(lane, pose);
        systems[lane]->holdProxy(pose);
      }
    }
    batch.step(static_cast<double>(i) * h, h);
    for (int lane = 0; lane < kLanes; ++lane) {
      rk4.step(*systems[lane], static_cast<double>(i) * h, scalar[lane], h);
      ASSERT_TRUE(sameBits<12>(batch.state(lane), scalar[lane]))
          << "width " << width << ", method " << (method ? physics::forceMethodName(*method) : "free") << ", lane "
          << lane << ", step " << i;
    }
  }
}

TEST(BatchedRk4Test, ForceDrivenLanesHaveTheScalarBitsFreeAndCoupled) {
  for (int width : supportedWidths()) {
    expectForceDrivenLanesMatchScalar(width, std::nullopt);
    for (ForceMethod m : {ForceMethod::M1, ForceMethod::M2, ForceMethod::M3})
      expectForceDrivenLanesMatchScalar(width, m);
  }
}

TEST(BatchedRk4Test, ALaneCoupledByAnotherMethodIsRefused) {
  physics::ForceDrivenBatch batch(ForceMethod::M3, 1);
  CouplingDef m1;
  m1.method = ForceMethod::M1;
  EXPECT_THROW(batch.add(HemisphereParams{}, m1, ForceDrivenState::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace hemiroll::test
