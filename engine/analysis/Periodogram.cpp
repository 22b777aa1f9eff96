#include "engine/analysis/Periodogram.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <utility>
#include <vector>

namespace hemiroll::analysis {

namespace {

struct FftwFree {
  void operator()(fftw_complex* p) const { fftw_free(p); }
};
using FftwBuffer = std::unique_ptr<fftw_complex[], FftwFree>;

FftwBuffer fftwBuffer(std::size_t length) {
  return FftwBuffer(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * length)));
}

// One out-of-place plan per (power-of-two length, direction), made once and
// kept for the process: at most 2 x 64 of them, each executed on any two
// distinct fftw_malloc'd buffers of its length (fftw_execute_dft is
// thread-safe; the planner is not, hence the lock). Out of place because
// FFTW_ESTIMATE's in-place plan of 8192 points copies through a buffer and
// ran ~10 % slower (30.6 against 27.5 us here). Why powers of two: planning a transform
// of an awkward length (4 x 5961 = 4 x 3^1 x 1987) cost FFTW ~3 ms even
// with FFTW_ESTIMATE, more than the transform, and a sweep's windows have
// as many lengths as points.
fftw_plan planOf(std::size_t length, int direction) {
  static std::mutex lock;
  static std::map<std::pair<std::size_t, int>, fftw_plan> plans;
  const std::lock_guard<std::mutex> guard(lock);
  fftw_plan& plan = plans[{length, direction}];
  if (plan == nullptr) {
    // FFTW_ESTIMATE: chosen by rule, the buffer untouched while planning.
    const FftwBuffer in = fftwBuffer(length), out = fftwBuffer(length);
    plan = fftw_plan_dft_1d(static_cast<int>(length), in.get(), out.get(), direction, FFTW_ESTIMATE);
  }
  return plan;
}

std::size_t powerOfTwoAtLeast(std::size_t n) {
  std::size_t p = 1;
  while (p < n) p *= 2;
  return p;
}

// Each thread's transform buffers (the signal, its spectrum, the filter's),
// grown as needed and kept (a sweep's worker analyses many points of one
// length; no allocation per search). The filter's transform depends only on
// the key below, so a search of the same shape as the last one (a sweep
// point's three searches, on one window) reuses it.
struct FilterKey {
  std::size_t length = 0, fftLength = 0, samples = 0, count = 0;
  bool operator==(const FilterKey&) const = default;
};
// The chirp c_j of one 2L, for j below its size: a value depends on j and
// 2L alone, so a search of another count or sample count
// with the same 2L reuses it (a sweep point's rose and helix searches have
// the same window, hence the same 2L = 2 x oversampling x n).
struct Chirp {
  std::int64_t twiceL = 0;
  std::vector<std::complex<double>> values;
};
// The factors w_m = exp(-2 pi i start m dt) c_m that multiply the
// samples: they depend on these alone, and a sweep point's three searches
// (the rose's, the helix's two sides) share them.
struct TurnKey {
  std::size_t samples = 0;
  std::int64_t twiceL = 0;
  double start = 0.0, dt = 0.0;
  bool operator==(const TurnKey&) const = default;
};
struct Workspace {
  std::size_t length = 0;
  FftwBuffer signal, spectrum, filter;
  Chirp chirp;
  FilterKey filterKey;  // what `filter` holds the transform of; empty: nothing
  std::vector<std::complex<double>> turned;  // w_m for turnedKey
  TurnKey turnedKey;                         // empty: nothing
  void reserve(std::size_t n) {
    if (n <= length) return;
    signal = fftwBuffer(n);
    spectrum = fftwBuffer(n);
    filter = fftwBuffer(n);
    length = n;
    filterKey = {};
  }
};

// exp(-i pi j^2 / L): the chirp, its phase reduced in integers (j^2
// mod 2L is exact below 2^63), so it is as accurate for j = 10^5 as for 1.
double chirpPhase(std::int64_t j, std::int64_t twiceL) {
  const std::int64_t r = (j * j) % twiceL;
  return -std::numbers::pi * 2.0 * static_cast<double>(r) / static_cast<double>(twiceL);
}

// Samples of exp(i phase) are made by complex products from an exact start
// every kRestart samples (issue 32: a sin and cos per sample had been 5 % of
// a sweep). A product errs by a few eps, so after k products a value errs by
// about k eps (a linear phase) or k^2 eps / 2 (the chirp, whose ratio is
// itself made by products): at most ~32^2 / 2 eps = 1e-13 here, far inside
// the grid's tolerance (PeriodogramTest: 1e-10 of the largest power).
constexpr std::size_t kRestart = 32;

// (a + bi)(c + di) = (ac - bd) + (ad + bc)i: the very operations of the
// compiler's complex product, without its recovery of infinities (C Annex
// G), which cannot fire on the finite values here (the samples are finite:
// DominantTone searches no other; the chirps and shifts have modulus 1).
// Without its branches the loops below run side by side or vectorise.
inline std::complex<double> times(std::complex<double> a, std::complex<double> b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// Each run of kRestart samples is a chain of dependent products from its
// exact start; kSideBySide runs advance together, so that the CPU overlaps
// their chains instead of waiting on one (each run does exactly the
// products it did alone, so the same bits).
constexpr std::size_t kSideBySide = 8;

// c_j = exp(-i pi j^2 / L) for j = 0 .. count - 1. From j to j + 1 the
// phase grows by -pi (2 j + 1) / L, and that step by -2 pi / L.
void chirps(std::int64_t twiceL, std::size_t count, std::complex<double>* out) {
  const std::complex<double> stepRatio = std::polar(1.0, -2.0 * std::numbers::pi * 2.0 / static_cast<double>(twiceL));
  for (std::size_t run = 0; run * kRestart < count; run += kSideBySide) {
    std::complex<double> c[kSideBySide], step[kSideBySide];
    const std::size_t runs = std::min(kSideBySide, (count - run * kRestart + kRestart - 1) / kRestart);
    for (std::size_t g = 0; g < runs; ++g) {
      const auto jj = static_cast<std::int64_t>((run + g) * kRestart);
      c[g] = std::polar(1.0, chirpPhase(jj, twiceL));
      const std::int64_t odd = (2 * jj + 1) % twiceL;
      step[g] = std::polar(1.0, -std::numbers::pi * 2.0 * static_cast<double>(odd) / static_cast<double>(twiceL));
    }
    for (std::size_t r = 0; r < kRestart; ++r) {
      for (std::size_t g = 0; g < runs; ++g) {
        const std::size_t j = (run + g) * kRestart + r;
        if (j >= count) continue;
        out[j] = c[g];
        c[g] = times(c[g], step[g]);
        step[g] = times(step[g], stepRatio);
      }
    }
  }
}

}  // namespace

// The grid's k-th power is |X_k|^2 with X_k = sum_m a_m w^(k m), a_m the
// shifted samples and w = exp(-2 pi i / fftLength): a transform of
// fftLength points read at its first `count` bins. Bluestein's identity
// k m = (k^2 + m^2 - (k - m)^2) / 2 makes it a convolution,
//   X_k = c_k sum_m (a_m c_m) conj(c_(k-m)),   c_j = w^(j^2 / 2),
// of n samples with count + n - 1 chirp values, done by transforms of a
// power of two P >= n + count - 1. |c_k| = 1, so the power is |y_k|^2 / P^2.
void fftGridPowers(std::span<const std::complex<double>> samples, double dt, std::size_t fftLength, double start,
                   std::size_t count, std::span<double> out) {
  const std::size_t n = samples.size();
  if (count == 0) return;
  if (n == 0) {
    for (std::size_t k = 0; k < count; ++k) out[k] = 0.0;
    return;
  }
  const std::size_t length = powerOfTwoAtLeast(n + count - 1);
  thread_local Workspace work;
  work.reserve(length);
  fftw_complex* a = work.signal.get();
  fftw_complex* spectrum = work.spectrum.get();
  fftw_complex* h = work.filter.get();
  const auto twiceL = static_cast<std::int64_t>(2 * fftLength);
  Chirp& chirp = work.chirp;
  if (chirp.twiceL != twiceL || chirp.values.size() < std::max(n, count)) {
    chirp.twiceL = twiceL;
    chirp.values.resize(std::max(n, count));
    chirps(twiceL, chirp.values.size(), chirp.values.data());
  }
  const std::complex<double>* c = chirp.values.data();
  // The shift that puts `start` on bin 0, exp(-2 pi i start m dt), times
  // the chirp c_m: w_m, made once for a search's shape (each w_m by the
  // very products a search made for it alone, so the same bits).
  const TurnKey turnKey{n, twiceL, start, dt};
  if (!(work.turnedKey == turnKey)) {
    work.turned.resize(n);
    const double turn = -2.0 * std::numbers::pi * start * dt;
    const std::complex<double> turnStep = std::polar(1.0, turn);
    for (std::size_t run = 0; run * kRestart < n; run += kSideBySide) {
      std::complex<double> shift[kSideBySide];
      const std::size_t runs = std::min(kSideBySide, (n - run * kRestart + kRestart - 1) / kRestart);
      for (std::size_t g = 0; g < runs; ++g) shift[g] = std::polar(1.0, turn * static_cast<double>((run + g) * kRestart));
      for (std::size_t r = 0; r < kRestart; ++r) {
        for (std::size_t g = 0; g < runs; ++g) {
          const std::size_t m = (run + g) * kRestart + r;
          if (m >= n) continue;
          work.turned[m] = times(shift[g], c[m]);
          shift[g] = times(shift[g], turnStep);
        }
      }
    }
    work.turnedKey = turnKey;
  }
  const std::complex<double>* w = work.turned.data();
  for (std::size_t m = 0; m < n; ++m) {
    const std::complex<double> z = times(samples[m], w[m]);
    a[m][0] = z.real();
    a[m][1] = z.imag();
  }
  for (std::size_t m = n; m < length; ++m) a[m][0] = a[m][1] = 0.0;
  const FilterKey key{length, fftLength, n, count};
  if (!(work.filterKey == key)) {
    // conj(c_j) at j = 0 .. count - 1 and, wrapped round, j = -(n - 1) .. -1,
    // laid out in `spectrum` (free until the signal's transform) and
    // transformed into `filter`.
    fftw_complex* chirped = spectrum;
    for (std::size_t m = 0; m < length; ++m) chirped[m][0] = chirped[m][1] = 0.0;
    for (std::size_t j = 0; j < count; ++j) {
      chirped[j][0] = c[j].real();
      chirped[j][1] = -c[j].imag();
    }
    for (std::size_t j = 1; j < n; ++j) {
      chirped[length - j][0] = c[j].real();
      chirped[length - j][1] = -c[j].imag();
    }
    fftw_execute_dft(planOf(length, FFTW_FORWARD), chirped, h);
    work.filterKey = key;
  }
  fftw_execute_dft(planOf(length, FFTW_FORWARD), a, spectrum);
  for (std::size_t m = 0; m < length; ++m) {
    const std::complex<double> product = times({spectrum[m][0], spectrum[m][1]}, {h[m][0], h[m][1]});
    spectrum[m][0] = product.real();
    spectrum[m][1] = product.imag();
  }
  fftw_execute_dft(planOf(length, FFTW_BACKWARD), spectrum, a);
  const double scale = 1.0 / (static_cast<double>(length) * static_cast<double>(length));
  for (std::size_t k = 0; k < count; ++k) out[k] = (a[k][0] * a[k][0] + a[k][1] * a[k][1]) * scale;
}

}  // namespace hemiroll::analysis
