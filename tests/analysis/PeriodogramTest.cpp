// engine/analysis Periodogram: the grid's powers by Bluestein's chirp-z
// convolution against the direct sum (periodogramPowers) on random signals.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <complex>
#include <iostream>
#include <random>
#include <span>
#include <thread>
#include <vector>

#include "engine/analysis/DominantTone.h"
#include "engine/analysis/Periodogram.h"

namespace hemiroll::analysis {
namespace {

// The tolerance, relative to the grid's largest power: an FFT of P points
// errs by about eps log2(P) of its input's norm, so the convolution's value
// at a bin errs by about eps log2(P) sqrt(n + count) |z| |chirp| / sqrt(P),
// and its power by twice that relative to the largest. For the longest case
// here (n = 60 001, P = 2^17) that is ~2e-16 x 17 x 300 = 1e-12 of a
// noise peak, and the chirps made by products from exact restarts every 32
// samples add at most ~32^2 / 2 eps = 1e-13; 1e-10 leaves a factor of about
// 100 (the largest error seen is printed: 1.7e-13 on this machine). DominantTone re-evaluates by the direct sum whatever lies
// within kNearTie = 1e-9 of the top, so this is also the margin it needs.
constexpr double kRelativeTolerance = 1e-10;

struct Case {
  std::size_t n;         // samples
  int oversampling;      // fftLength = oversampling x n
  double start;          // [Hz] the grid's first frequency
  std::size_t count;     // grid frequencies
  bool real;             // y = 0 (the rose's rho)
};

// The grid on one side: f = sign (start + k df), the negative side as the
// positive side of conj(z), as Periodogram.h has it.
std::vector<double> sideOf(std::span<const std::complex<double>> z, int sign, double dt, std::size_t fftLength,
                           double start, std::size_t count) {
  std::vector<std::complex<double>> side(z.begin(), z.end());
  if (sign < 0)
    for (auto& v : side) v = std::conj(v);
  std::vector<double> powers(count);
  fftGridPowers(side, dt, fftLength, start, count, powers);
  return powers;
}

TEST(Periodogram, TheChirpZGridIsTheDirectSumOnRandomSignals) {
  std::mt19937 rng(32);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const double dt = 0.01;
  const Case cases[] = {
      {37, 4, 0.0, 30, false},      // shorter than any renormalisation block
      {1000, 4, 0.3, 400, false},
      {5961, 4, 0.05, 2385, true},  // a sweep window: 4 x 5961 = 4 x 3 x 1987, an awkward length
      {6001, 4, 1.0 / 15.0, 2401, false},
      {60001, 4, 0.02, 2000, true},  // 600 s at 100 Hz
      {500, 4, 0.0, 1900, false},    // more frequencies than samples: the chirp beyond n
  };
  double worst = 0.0;
  for (const Case& c : cases) {
    std::vector<std::complex<double>> z;
    for (std::size_t i = 0; i < c.n; ++i) {
      // Noise, a random offset and a tone of random frequency and amplitude.
      const double t = static_cast<double>(i) * dt;
      const double tone = uniform(rng) * std::cos(2.0 * 3.14159 * 2.0 * std::abs(uniform(rng) + 1.0) * t);
      z.emplace_back(noise(rng) + tone + 0.3, c.real ? 0.0 : noise(rng));
    }
    const std::size_t fftLength = static_cast<std::size_t>(c.oversampling) * c.n;
    const double df = 1.0 / (static_cast<double>(fftLength) * dt);
    for (const int sign : {+1, -1}) {
      std::vector<double> direct(c.count), freqs(c.count);
      for (std::size_t k = 0; k < c.count; ++k) freqs[k] = sign * (c.start + static_cast<double>(k) * df);
      const std::vector<double> chirpZ = sideOf(z, sign, dt, fftLength, c.start, c.count);
      periodogramPowers(z, freqs, dt, direct);
      const double top = *std::max_element(direct.begin(), direct.end());
      ASSERT_GT(top, 0.0);
      for (std::size_t k = 0; k < c.count; ++k) {
        ASSERT_NEAR(chirpZ[k], direct[k], kRelativeTolerance * top) << "n " << c.n << " sign " << sign << " bin " << k;
        worst = std::max(worst, std::abs(chirpZ[k] - direct[k]) / top);
      }
    }
  }
  std::cout << "largest difference / largest power: " << worst << "\n";
}

// A thread keeps the filter's transform for the next search of the same
// shape (a sweep's points): another signal and start with it must still be
// the direct sum's.
TEST(Periodogram, TheKeptFilterServesAnotherSignalOfTheSameShape) {
  std::mt19937 rng(321);
  std::normal_distribution<double> noise(0.0, 1.0);
  const std::size_t n = 800, fftLength = 4 * n, count = 300;
  const double dt = 0.01, df = 1.0 / (static_cast<double>(fftLength) * dt);
  for (const double start : {0.2, 0.7, 0.2}) {
    std::vector<std::complex<double>> z;
    for (std::size_t i = 0; i < n; ++i) z.emplace_back(noise(rng), noise(rng));
    std::vector<double> chirpZ(count), direct(count), freqs(count);
    for (std::size_t k = 0; k < count; ++k) freqs[k] = start + static_cast<double>(k) * df;
    fftGridPowers(z, dt, fftLength, start, count, chirpZ);
    periodogramPowers(z, freqs, dt, direct);
    const double top = *std::max_element(direct.begin(), direct.end());
    for (std::size_t k = 0; k < count; ++k) ASSERT_NEAR(chirpZ[k], direct[k], kRelativeTolerance * top) << start << " " << k;
  }
}

// A thread keeps the filter's transform and the shifted chirp for the next
// search of the same shape, and a sweep point's searches come in runs of one
// shape with other signals: each search must give the very bits a thread
// that kept nothing gives it, whatever searches went before.
TEST(Periodogram, KeptTransformsGiveTheBitsOfAFreshSearch) {
  std::mt19937 rng(99);
  std::normal_distribution<double> noise(0.0, 1.0);
  const std::size_t n = 600, fftLength = 4 * n, count = 250;
  const double dt = 0.01;
  struct Search {
    int sign;
    double start;
  };
  for (const Search s : {Search{+1, 0.3}, {+1, 0.3}, {-1, 0.3}, {+1, 0.3}, {+1, 0.5}, {-1, 0.5}, {-1, 0.5}}) {
    std::vector<std::complex<double>> z;
    for (std::size_t i = 0; i < n; ++i) z.emplace_back(noise(rng), noise(rng));
    auto search = [&] { return sideOf(z, s.sign, dt, fftLength, s.start, count); };
    const std::vector<double> kept = search();
    std::vector<double> fresh;
    std::thread([&] { fresh = search(); }).join();  // a new thread: nothing kept
    for (std::size_t k = 0; k < count; ++k)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(kept[k]), std::bit_cast<std::uint64_t>(fresh[k]))
          << s.sign << " " << s.start << " " << k;
  }
}

// No samples: every power is 0 (not a transform of a negative length).
TEST(Periodogram, NoSamplesGiveZeroPowers) {
  std::vector<double> powers(5, 1.0);
  fftGridPowers({}, 0.01, 16, 0.1, powers.size(), powers);
  for (double p : powers) EXPECT_EQ(p, 0.0);
}

// A bin in the wrong place would be far outside the tolerance: a tone on
// bin 7 shows there and not on its neighbours.
TEST(Periodogram, ATonePeaksOnItsBin) {
  const std::size_t n = 500, fftLength = 4 * n, count = 40;
  const double dt = 0.01, start = 0.1, df = 1.0 / (static_cast<double>(fftLength) * dt);
  std::vector<std::complex<double>> z;
  for (std::size_t i = 0; i < n; ++i)
    z.push_back(std::polar(1.0, 2.0 * 3.141592653589793 * (start + 7.0 * df) * static_cast<double>(i) * dt));
  std::vector<double> powers(count);
  fftGridPowers(z, dt, fftLength, start, count, powers);
  EXPECT_EQ(std::max_element(powers.begin(), powers.end()) - powers.begin(), 7);
  EXPECT_NEAR(powers[7], static_cast<double>(n * n), 1e-9 * static_cast<double>(n * n));
}

}  // namespace
}  // namespace hemiroll::analysis
