// What `hemiroll analyze` costs as a recording grows (issue 33, item 4):
//   BM_AnalyzeTrial/<minutes>  the features of one trial (phases, the rose
//     on the mass point's path, the helix on the contact trace; every
//     periodogram by FFT) from 1 minute to 24 hours at the recorder's
//     100 Hz: the paper's rose on the face (k = 8, Omega = -pi/10), a
//     trochoid on the plane, psi = -0.1 t. The samples are made outside the
//     timed loop. CPU time; Complexity() fits it: before the FFT an hour took
//     13 s (quadratic), a day would have taken about two and a half hours.
//   BM_Periodogram/<samples>  one tone search's grid, by FFT and by the
//     direct sum it replaced (BM_PeriodogramDirect), on the same signal.
#include <benchmark/benchmark.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "engine/analysis/Analysis.h"
#include "tests/analysis/support/Synthetic.h"

namespace {

using namespace hemiroll;

constexpr double kRate = 100.0;  // [Hz] the recorder's default (RECORDING.md)

struct Trial {
  test::Planar mass, contact;
  std::vector<double> psi;
  analysis::TrialSamples samples() const { return {mass.t, mass.x, mass.y, contact.x, contact.y, psi}; }
};

Trial trialOf(double minutes) {
  const double duration = 60.0 * minutes;
  Trial trial;
  trial.mass = test::rose(0.015, 0.008, 8, -std::numbers::pi / 10, duration, kRate);
  trial.contact = test::trochoidArc(0.05, 0.002, 0.002, 9 * std::numbers::pi / 10, 0.0, duration, kRate);
  for (double t : trial.mass.t) trial.psi.push_back(-0.1 * t);
  return trial;
}

void BM_AnalyzeTrial(benchmark::State& state) {
  const Trial trial = trialOf(static_cast<double>(state.range(0)));
  for (auto _ : state) {
    const analysis::TrialFeatures features = analysis::analyzeTrial(trial.samples());
    benchmark::DoNotOptimize(features.rose.leaves);
  }
  state.SetComplexityN(static_cast<benchmark::IterationCount>(trial.mass.t.size()));
  state.counters["samples"] = static_cast<double>(trial.mass.t.size());
}
BENCHMARK(BM_AnalyzeTrial)
    ->Arg(1)->Arg(10)->Arg(60)->Arg(240)->Arg(1440)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Complexity(benchmark::oNLogN);

std::vector<std::complex<double>> tone(std::size_t n) {
  std::vector<std::complex<double>> z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = std::polar(1.0, 2.0 * std::numbers::pi * 1.3 * static_cast<double>(i) / kRate);
  return z;
}

void periodogram(benchmark::State& state, bool direct) {
  const std::vector<std::complex<double>> z = tone(static_cast<std::size_t>(state.range(0)));
  analysis::ToneSearch search;
  search.minFrequency = 0.1;
  search.directSum = direct;
  for (auto _ : state) benchmark::DoNotOptimize(analysis::dominantTone(z, 1.0 / kRate, search).frequency);
  state.SetComplexityN(state.range(0));
}
void BM_Periodogram(benchmark::State& state) { periodogram(state, false); }
void BM_PeriodogramDirect(benchmark::State& state) { periodogram(state, true); }
BENCHMARK(BM_Periodogram)->RangeMultiplier(4)->Range(1 << 10, 1 << 16)->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_PeriodogramDirect)->RangeMultiplier(4)->Range(1 << 10, 1 << 16)->Unit(benchmark::kMillisecond)->Complexity();

}  // namespace

BENCHMARK_MAIN();
