// Cost of one right-hand side and one RK4 step for both models, on states
// typical of play (tilted, spinning, mass point off centre). Targets on the
// 2-core development machine: one RK4 step of the 12-state model <= 250 ns.
// The lockstep benchmarks (BatchedRk4.h) step 64 trajectories a time at each
// lane width; compare their items_per_second (trajectory steps per second)
// with the scalar RK4 steps' (issue 16: at least 3x on one core).
#include <benchmark/benchmark.h>

#include <vector>

#include "engine/physics/Physics.h"

namespace {

using namespace hemiroll::physics;

ForceDrivenState typicalState() {
  ForceDrivenState x;
  // psi beyond pi/4 so that its sin/cos takes the full reduction, as in long play.
  x << 0.012, -0.006, 0.03, 0.02, 0.4, -0.3, 1.2, 0.01, -0.02, 0.25, -0.15, 2.3;
  return x;
}

ProxyPose typicalProxy() {
  ProxyPose pose;
  pose.position = Vec3(0.015, -0.004, 0.045);
  pose.velocity = Vec3(0.01, 0.02, 0.0);
  return pose;
}

void configure(ForceDrivenSystem& system, int mode) {
  if (mode == 0) system.setFree();
  if (mode == 1) {
    system.setCoupling(CouplingDef{});  // M3, paper gains
    system.holdProxy(typicalProxy());
  }
}

void BM_ForceDrivenDerivative(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  configure(system, static_cast<int>(state.range(0)));
  ForceDrivenState x = typicalState(), dx;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    system.derivative(0.0, x, dx);
    benchmark::DoNotOptimize(dx);
  }
}
BENCHMARK(BM_ForceDrivenDerivative)->Arg(0)->Arg(1)->ArgName("coupledM3");

void BM_ForceDrivenRk4Step(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  configure(system, static_cast<int>(state.range(0)));
  RungeKutta4<12> rk4;
  const ForceDrivenState x0 = typicalState();
  ForceDrivenState x = x0;
  for (auto _ : state) {
    rk4.step(system, 0.0, x, 1e-3);
    benchmark::DoNotOptimize(x);
    x = x0;  // stay on a typical state rather than drift away from it
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ForceDrivenRk4Step)->Arg(0)->Arg(1)->ArgName("coupledM3");

// One right-hand side waiting on the one before, as RK4's stages do (issue
// 32, item 4): each evaluation's input is the stage x0 + (h/2) dx formed
// from the previous one's output, so this is the latency of an evaluation
// plus a stage, where BM_ForceDrivenDerivative (independent calls on one
// input, overlapped by the CPU) is its throughput. Four of these plus the
// final combination are what an RK4 step cannot go below.
void BM_ForceDrivenDerivativeChained(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  configure(system, static_cast<int>(state.range(0)));
  const ForceDrivenState x0 = typicalState();
  ForceDrivenState x = x0, dx;
  for (auto _ : state) {
    system.derivative(0.0, x, dx);
    for (int i = 0; i < 12; ++i) x[i] = x0[i] + 5e-4 * dx[i];
  }
  benchmark::DoNotOptimize(x);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ForceDrivenDerivativeChained)->Arg(0)->Arg(1)->ArgName("coupledM3");

// Where the chain runs: as above (free), but only the slots in the mask feed
// the next evaluation; the others stay at x0. Dropping a group that is on the
// longest path shortens the latency; dropping one that is not leaves it.
// Masks: 0xfff all, 0x1ff all but the tilt angles and psi (slots 9-11),
// 0x7ff all but psi, 0xe00 the angles only, 0x070 w only, 0x00f p and p' only.
void BM_ForceDrivenChainedSlots(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  system.setFree();
  const unsigned mask = static_cast<unsigned>(state.range(0));
  const ForceDrivenState x0 = typicalState();
  ForceDrivenState x = x0, dx;
  for (auto _ : state) {
    system.derivative(0.0, x, dx);
    for (int i = 0; i < 12; ++i) x[i] = x0[i] + ((mask >> i) & 1u ? 5e-4 * dx[i] : 0.0);
  }
  benchmark::DoNotOptimize(x);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ForceDrivenChainedSlots)->Arg(0xfff)->Arg(0x1ff)->Arg(0x7ff)->Arg(0xe00)->Arg(0x070)->Arg(0x00f)->ArgName("mask");

// The same model with the orientation as a quaternion (RotationDrivenSystem.h),
// on the same state.
void configure(RotationDrivenSystem& system, int mode) {
  if (mode == 0) system.setFree();
  if (mode == 1) {
    system.setCoupling(CouplingDef{});
    system.holdProxy(typicalProxy());
  }
}

void BM_RotationDerivative(benchmark::State& state) {
  RotationDrivenSystem system{HemisphereParams{}};
  configure(system, static_cast<int>(state.range(0)));
  RotationState x = toRotationState(typicalState()), dx;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    system.derivative(0.0, x, dx);
    benchmark::DoNotOptimize(dx);
  }
}
BENCHMARK(BM_RotationDerivative)->Arg(0)->Arg(1)->ArgName("coupledM3");

void BM_RotationRk4Step(benchmark::State& state) {
  RotationDrivenSystem system{HemisphereParams{}};
  configure(system, static_cast<int>(state.range(0)));
  RungeKutta4<13> rk4;
  const RotationState x0 = toRotationState(typicalState());
  RotationState x = x0;
  for (auto _ : state) {
    rk4.step(system, 0.0, x, 1e-3);
    benchmark::DoNotOptimize(x);
    x = x0;
  }
}
BENCHMARK(BM_RotationRk4Step)->Arg(0)->Arg(1)->ArgName("coupledM3");

BodyState typicalBody() { return typicalState().tail<8>(); }

void BM_PrescribedDerivative(benchmark::State& state) {
  RoseDrive rose{RoseDef{}};
  PrescribedDriveSystem system{HemisphereParams{}, rose};
  BodyState x = typicalBody(), dx;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    system.derivative(1.3, x, dx);
    benchmark::DoNotOptimize(dx);
  }
}
BENCHMARK(BM_PrescribedDerivative);

void BM_PrescribedRk4Step(benchmark::State& state) {
  RoseDrive rose{RoseDef{}};
  PrescribedDriveSystem system{HemisphereParams{}, rose};
  RungeKutta4<8> rk4;
  const BodyState x0 = typicalBody();
  BodyState x = x0;
  for (auto _ : state) {
    rk4.step(system, 1.3, x, 1e-3);
    benchmark::DoNotOptimize(x);
    x = x0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PrescribedRk4Step);

// Lockstep: 64 trajectories, varied as a sweep varies them, back on their
// typical starts every 256 steps (a few per cent of a step's cost) so that
// the benchmark measures typical states rather than tipped-over ones.
constexpr int kLockstepLanes = 64;
constexpr int kLockstepRestart = 256;

void BM_PrescribedLockstepRk4(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  if (!laneWidthSupported(width)) {
    state.SkipWithError("this CPU does not run this lane width");
    return;
  }
  RoseBatch batch(width);
  std::vector<BodyState> starts;
  for (int lane = 0; lane < kLockstepLanes; ++lane) {
    RoseDef rose;
    rose.k = 4.0 + lane % 13;
    rose.omega = -1.0 + 0.08 * (lane / 13);
    starts.push_back(typicalBody());
    batch.add(HemisphereParams{}, rose, starts.back());
  }
  // The clock as a run keeps it (RoseLockstepRun): each step begins at the
  // grid time the last one ended on, so the kernel may reuse the rose there.
  const double t0 = 1.3, h = 1e-3;
  double start = t0;
  int steps = 0;
  for (auto _ : state) {
    const double target = t0 + static_cast<double>(steps + 1) * h;
    batch.step(start, h, target);
    start = target;
    if (++steps == kLockstepRestart) {
      for (int lane = 0; lane < kLockstepLanes; ++lane) batch.setState(lane, starts[lane]);
      start = t0;
      steps = 0;
    }
  }
  state.SetItemsProcessed(state.iterations() * kLockstepLanes);
}
BENCHMARK(BM_PrescribedLockstepRk4)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->ArgName("lanes");

void BM_ForceDrivenLockstepRk4(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  if (!laneWidthSupported(width)) {
    state.SkipWithError("this CPU does not run this lane width");
    return;
  }
  ForceDrivenBatch batch(ForceMethod::M3, width);
  for (int lane = 0; lane < kLockstepLanes; ++lane) {
    CouplingDef coupling;
    coupling.stiffness = 150.0 + 4.0 * lane;
    batch.add(HemisphereParams{}, coupling, typicalState());
    batch.holdProxy(lane, typicalProxy());
  }
  int steps = 0;
  for (auto _ : state) {
    batch.step(0.0, 1e-3);
    if (++steps == kLockstepRestart) {
      for (int lane = 0; lane < kLockstepLanes; ++lane) batch.setState(lane, typicalState());
      steps = 0;
    }
  }
  state.SetItemsProcessed(state.iterations() * kLockstepLanes);
}
BENCHMARK(BM_ForceDrivenLockstepRk4)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->ArgName("lanes");

// The stepper on top of RK4: domain checks every step, as the servo loop runs it.
void BM_StepperAdvance(benchmark::State& state) {
  ForceDrivenSystem system{HemisphereParams{}};
  configure(system, 1);
  RungeKutta4<12> rk4;
  const ForceDrivenState x0 = typicalState();
  Stepper<12> stepper(system, rk4, x0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(stepper.advance(1e-3));
    stepper.reset(x0, 0.0);  // a few ns; PauseTiming would cost far more
  }
}
BENCHMARK(BM_StepperAdvance);

}  // namespace

BENCHMARK_MAIN();
