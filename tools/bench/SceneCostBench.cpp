// Cost per simulated second of a scene, at the paper's h = 1 ms (one
// benchmark iteration = 1 s of simulated time = 1000 steps), to show what
// skipping unneeded work saves (issue 3, "Skip what a scene doesn't need"):
//   Full:     12-state M3 coupling to a moving proxy, and everything a CSV row
//             holds computed after every step (energy, hand and model forces,
//             face-frame force through the orientation matrix);
//   Minimal:  the same scene stepping only (rows only where written);
//   Free:     free motion, stepping only;
//   Sleeping: a scene at rest with a held proxy: the stepper sleeps at the
//             exact fixed point and only advances its clock;
//   AtRestAwake: the same scene at rest with sleeping impossible (an RK4 that
//             declares history), i.e. what sleeping saves;
//   Tether:   issue 3's "one hour of play" scene, an undamped M3 spring to a
//             fixed proxy, stepping only, in both orientation forms (contact
//             angles, 12 states; quaternion, 13 states). Times 3600 is the
//             hour (target: under 1 s, i.e. under 278 us per simulated second).
#include <benchmark/benchmark.h>

#include <cmath>

#include "engine/physics/Physics.h"

namespace {

using namespace hemiroll::physics;

constexpr double kStep = 1e-3;
constexpr int kStepsPerSecond = 1000;

// A slow small circle around the face centre's upright position.
class CircleProxy final : public ProxyTrajectory {
 public:
  ProxyPose at(double t) const override {
    constexpr double r = 0.003, w = 3.0;
    ProxyPose pose;
    pose.position = Vec3(r * std::cos(w * t), r * std::sin(w * t), 0.04);
    pose.velocity = Vec3(-r * w * std::sin(w * t), r * w * std::cos(w * t), 0.0);
    return pose;
  }
};

ForceDrivenState playStart() {
  ForceDrivenState x = ForceDrivenState::Zero();
  x[0] = 0.003;
  return x;
}

// Everything a trajectory row holds (game/research/sim/ScenarioRun.cpp's observe).
double fullRow(const ForceDrivenSystem& system, double t, const ForceDrivenState& x) {
  using namespace force_slot;
  const double energy = mechanicalEnergy(system.dynamics(), x).total();
  const CouplingForces forces = system.couplingForces(t, x);
  const Mat3 R = makeOrientation(x[u_o], x[v_o], x[psi]).R;
  return energy + R.col(0).dot(forces.modelForce) + R.col(1).dot(forces.modelForce) + forces.handForce.sum();
}

void BM_SceneFull(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  CircleProxy proxy;
  system.setCoupling(CouplingDef{}, proxy);
  RungeKutta4<12> rk4;
  for (auto _ : state) {
    Stepper<12> stepper(system, rk4, playStart());
    double sink = 0.0;
    for (int i = 0; i < kStepsPerSecond; ++i) {
      stepper.advance(kStep);
      sink += fullRow(system, stepper.time(), stepper.state());
    }
    benchmark::DoNotOptimize(sink);
    if (stepper.halted()) state.SkipWithError("the scene left the domain");
  }
  state.SetLabel("per simulated second");
}
BENCHMARK(BM_SceneFull)->Unit(benchmark::kMicrosecond);

void BM_SceneMinimal(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  CircleProxy proxy;
  system.setCoupling(CouplingDef{}, proxy);
  RungeKutta4<12> rk4;
  for (auto _ : state) {
    Stepper<12> stepper(system, rk4, playStart());
    for (int i = 0; i < kStepsPerSecond; ++i) stepper.advance(kStep);
    benchmark::DoNotOptimize(stepper.state());
    if (stepper.halted()) state.SkipWithError("the scene left the domain");
  }
  state.SetLabel("per simulated second");
}
BENCHMARK(BM_SceneMinimal)->Unit(benchmark::kMicrosecond);

void BM_SceneFreeMinimal(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  RungeKutta4<12> rk4;
  ForceDrivenState x0 = ForceDrivenState::Zero();
  x0[6] = 4.0;  // spinning upright: stays inside for the whole second
  x0[10] = 0.02;
  for (auto _ : state) {
    Stepper<12> stepper(system, rk4, x0);
    for (int i = 0; i < kStepsPerSecond; ++i) stepper.advance(kStep);
    benchmark::DoNotOptimize(stepper.state());
  }
  state.SetLabel("per simulated second");
}
BENCHMARK(BM_SceneFreeMinimal)->Unit(benchmark::kMicrosecond);

// RK4 that declares history, so that the stepper never sleeps with it.
class NeverSleepingRk4 final : public Integrator<12> {
 public:
  std::string_view name() const override { return "rk4-never-sleeps"; }
  int order() const override { return 4; }
  void step(const OdeSystem<12>& f, double t, ForceDrivenState& x, double h) override { inner_.step(f, t, x, h); }

 private:
  RungeKutta4<12> inner_;
};

template <class Method>
void atRest(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  system.setCoupling(CouplingDef{});
  Method method;
  for (auto _ : state) {
    Stepper<12> stepper(system, method, ForceDrivenState::Zero());
    for (int i = 0; i < kStepsPerSecond; ++i) {
      system.holdProxy({Vec3(0.0, 0.0, 0.04), Vec3::Zero()});  // the servo tick re-holds the same pose
      stepper.advance(kStep);
    }
    benchmark::DoNotOptimize(stepper.state());
  }
  state.SetLabel("per simulated second");
}

void BM_SceneSleeping(benchmark::State& state) { atRest<RungeKutta4<12>>(state); }
BENCHMARK(BM_SceneSleeping)->Unit(benchmark::kMicrosecond);

void BM_SceneAtRestAwake(benchmark::State& state) { atRest<NeverSleepingRk4>(state); }
BENCHMARK(BM_SceneAtRestAwake)->Unit(benchmark::kMicrosecond);

}  // namespace

// The undamped tether from 3 mm off the proxy, spinning slowly: it never
// settles, so nothing sleeps.
template <int N, class System>
void tether(benchmark::State& state, const StateVector<N>& x0) {
  System system{HemisphereParams{}};
  CouplingDef def;
  def.damping = 0.0;
  system.setCoupling(def);
  system.holdProxy(ProxyPose{Vec3(0.0, 0.0, 0.04), Vec3::Zero()});
  RungeKutta4<N> rk4;
  for (auto _ : state) {
    Stepper<N> stepper(system, rk4, x0);
    for (int i = 0; i < kStepsPerSecond; ++i) stepper.advance(kStep);
    benchmark::DoNotOptimize(stepper.state());
  }
}

ForceDrivenState tetherStart() {
  ForceDrivenState x = playStart();
  x[force_slot::w_z] = 0.5;
  return x;
}

void BM_TetherAngles(benchmark::State& state) { tether<12, ForceDrivenSystem>(state, tetherStart()); }
BENCHMARK(BM_TetherAngles)->Unit(benchmark::kMicrosecond);

void BM_TetherQuaternion(benchmark::State& state) {
  tether<13, RotationDrivenSystem>(state, toRotationState(tetherStart()));
}
BENCHMARK(BM_TetherQuaternion)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
