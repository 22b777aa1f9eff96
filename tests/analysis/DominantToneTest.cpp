// engine/analysis DominantTone: the strongest periodic component and its clarity.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include "engine/analysis/DominantTone.h"
#include "engine/analysis/Periodogram.h"

namespace hemiroll::analysis {
namespace {

// The one-frequency sum written plainly with std::complex: the definition
// periodogramPowers must reproduce to the bit, whichever chains it shares.
double onePower(const std::vector<std::complex<double>>& z, double f, double dt) {
  const double step = -2.0 * std::numbers::pi * f * dt;
  const std::complex<double> rotate(std::cos(step), std::sin(step));
  std::complex<double> phasor(1.0, 0.0), sum(0.0, 0.0);
  for (std::size_t n = 0; n < z.size(); ++n) {
    sum += z[n] * phasor;
    phasor *= rotate;
    if ((n & 255u) == 255u) phasor /= std::abs(phasor);
  }
  return std::norm(sum);
}

TEST(DominantTone, PeriodogramPowersHaveTheBitsOfOneFrequencyAtATime) {
  std::mt19937 rng(26);
  std::normal_distribution<double> noise(0.0, 1.0);
  // 1000 samples (the renormalisation every 256 included); 13 frequencies:
  // not a multiple of the chains, both signs, zero among them.
  std::vector<std::complex<double>> z;
  for (int i = 0; i < 1000; ++i) z.emplace_back(noise(rng), noise(rng));
  std::vector<double> freqs;
  for (int k = -6; k <= 6; ++k) freqs.push_back(0.37 * k);
  std::vector<double> powers(freqs.size(), -1.0);
  periodogramPowers(z, freqs, 0.01, powers);
  for (std::size_t k = 0; k < freqs.size(); ++k)
    EXPECT_EQ(powers[k], onePower(z, freqs[k], 0.01)) << "f = " << freqs[k];
}

TEST(DominantTone, FindsAClockwiseToneBesideADrift) {
  // 0.45 Hz clockwise circle of 8 mm on top of a linear drift: over 35 s at 100 Hz.
  std::vector<std::complex<double>> z;
  const double dt = 0.01;
  for (int i = 0; i < 3500; ++i) {
    const double t = i * dt;
    z.push_back(0.008 * std::polar(1.0, -2 * std::numbers::pi * 0.45 * t) + std::complex<double>(0.001 * t, 0.0));
  }
  const Tone tone = dominantTone(z, dt, {.minFrequency = 3.0 / 35.0, .maxFrequency = 5.0});
  ASSERT_TRUE(tone.found);
  // The grid is 1 / (4 T) = 0.007 Hz fine, refined by a parabola: well within 0.005 Hz.
  EXPECT_NEAR(tone.frequency, -0.45, 0.005);
  // The Hann taper's scalloping loss at a quarter bin off is below 2 %.
  EXPECT_NEAR(tone.amplitude, 0.008, 0.0003);
  // The drift's variance (0.035^2 / 12 = 1e-4 m^2) besides the circle's 6.4e-5.
  EXPECT_NEAR(tone.share, 6.4e-5 / (6.4e-5 + 0.035 * 0.035 / 12.0), 0.02);
}

TEST(DominantTone, RealCosineGivesItsAmplitudeAndFullShare) {
  std::vector<std::complex<double>> z;
  for (int i = 0; i < 2000; ++i) z.emplace_back(0.3 + 0.05 * std::cos(2 * std::numbers::pi * 1.3 * i * 0.01 + 0.4), 0.0);
  const Tone tone = dominantTone(z, 0.01, {.minFrequency = 0.2, .maxFrequency = 5.0, .bothSigns = false});
  ASSERT_TRUE(tone.found);
  EXPECT_NEAR(tone.frequency, 1.3, 0.005);
  EXPECT_NEAR(tone.amplitude, 0.05, 0.002);  // within the taper's scalloping (2 %) and its leakage at 26 periods
  EXPECT_GT(tone.share, 0.95);
}

TEST(DominantTone, ALongFinelySampledSignalIsAveragedFirstAndKeepsItsTone) {
  // 100 s at 1 kHz (100k rows): searched as it is, 4000 grid frequencies x
  // 100k samples took over a minute (issue 19). Block-averaged, the tone
  // and its amplitude are the same within the grid and the boxcar's loss.
  std::vector<std::complex<double>> z;
  for (int i = 0; i < 100000; ++i) z.emplace_back(0.05 * std::cos(2 * std::numbers::pi * 1.3 * i * 0.001 + 0.4), 0.0);
  const Tone tone = dominantTone(z, 0.001, {.minFrequency = 0.2, .maxFrequency = 5.0, .bothSigns = false});
  ASSERT_TRUE(tone.found);
  EXPECT_LT(tone.samplesUsed, z.size());
  EXPECT_LE(static_cast<double>(tone.samplesUsed) * 4.8 * 100.0 * 4, kMaxToneWork);  // grid x samples within the budget
  EXPECT_NEAR(tone.frequency, 1.3, 0.001);
  // A boxcar of k samples at 1.3 Hz keeps sin(pi f k dt) / (pi f k dt) > 0.99 of it for k dt < 0.06 s.
  EXPECT_NEAR(tone.amplitude, 0.05, 0.002);
  // Short signals are searched as they are.
  z.resize(2000);
  EXPECT_EQ(dominantTone(z, 0.001, {.minFrequency = 0.2, .maxFrequency = 5.0, .bothSigns = false}).samplesUsed, 2000u);
}

TEST(DominantTone, ASlowTurnIsNoTone) {
  // A velocity turning slowly (an arc's tangent) peaks at the band's lower
  // edge: the tail of something slower than the band, not a tone in it.
  std::vector<std::complex<double>> z;
  for (int i = 0; i < 3000; ++i) z.push_back(0.002 * std::polar(1.0, 0.04 * i * 0.01));
  const Tone tone = dominantTone(z, 0.01, {.minFrequency = 0.1, .maxFrequency = 5.0});
  EXPECT_TRUE(!tone.found || tone.share < 0.2) << tone.frequency << " " << tone.share;
}

TEST(DominantTone, WhiteNoiseHasNoClearPeak) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<std::complex<double>> z;
    for (int i = 0; i < 3000; ++i) z.emplace_back(normal(random), normal(random));
    const Tone tone = dominantTone(z, 0.01, {.minFrequency = 0.1, .maxFrequency = 5.0});
    ASSERT_TRUE(tone.found);
    // 3000 samples: the strongest bin holds about 1.5 ln(3000) / 3000 = 0.4 %
    // of the power (DominantTone.h); 0.2 is fifty times that.
    EXPECT_LT(tone.share, 0.02) << "trial " << trial;
  }
}

TEST(DominantTone, ConstantOrTooShortSignalsHaveNoTone) {
  const std::vector<std::complex<double>> still(100, {0.01, 0.02});
  EXPECT_FALSE(dominantTone(still, 0.01, {}).found);
  const std::vector<std::complex<double>> few(4, {0.0, 1.0});
  EXPECT_FALSE(dominantTone(few, 0.01, {}).found);
}

// The FFT's grid (issue 33) is the direct sum's: the same frequencies,
// powers equal to round-off. An FFT of N points errs by about eps log2(N)
// of the largest power; 1e-10 of it leaves four orders of room.
TEST(DominantTone, TheFftGridIsTheDirectSumsGrid) {
  std::mt19937 rng(33);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<std::complex<double>> z;
  for (int i = 0; i < 1500; ++i) z.emplace_back(noise(rng) + std::cos(0.3 * i), noise(rng));
  const double dt = 0.01, start = 0.137;
  const std::size_t fftLength = 4 * z.size(), count = 400;
  const double df = 1.0 / (static_cast<double>(fftLength) * dt);
  for (const int sign : {+1, -1}) {
    std::vector<double> fft(count), direct(count), freqs(count);
    for (std::size_t k = 0; k < count; ++k) freqs[k] = sign * (start + static_cast<double>(k) * df);
    std::vector<std::complex<double>> side(z);  // the negative side: the positive side of conj(z) (Periodogram.h)
    if (sign < 0)
      for (auto& v : side) v = std::conj(v);
    fftGridPowers(side, dt, fftLength, start, count, fft);
    periodogramPowers(z, freqs, dt, direct);
    const double top = *std::max_element(direct.begin(), direct.end());
    for (std::size_t k = 0; k < count; ++k) EXPECT_NEAR(fft[k], direct[k], 1e-10 * top) << sign << " " << k;
  }
}

// The tone found through the FFT is the direct sum's to the bit: the peak's
// neighbourhood, the refinement and the amplitude are computed by the direct
// sum, and near-ties are settled by it. Pure and noisy, complex and real,
// short and block-averaged signals, tones on and between grid frequencies.
TEST(DominantTone, TheFftFindsTheDirectSumsToneBitForBit) {
  std::mt19937 rng(34);
  std::normal_distribution<double> noise(0.0, 1.0);
  struct Case {
    std::size_t n;
    double dt, f, noise;
    ToneSearch search;
  };
  const Case cases[] = {
      {3500, 0.01, -0.45, 0.0, {.minFrequency = 3.0 / 35.0, .maxFrequency = 5.0}},
      {3500, 0.01, 1.2345, 0.5, {.minFrequency = 0.1, .maxFrequency = 5.0}},
      {2000, 0.01, 0.8, 2.0, {.minFrequency = 0.0, .maxFrequency = 5.0}},  // f = 0 once on the grid
      {2000, 0.01, 2.05, 0.3, {.minFrequency = 0.2, .maxFrequency = 5.0, .bothSigns = false}},
      {120000, 0.001, 0.95, 0.2, {.minFrequency = 0.2, .maxFrequency = 5.0, .bothSigns = false}},  // block-averaged
      {5000, 0.01, 0.5, 50.0, {.minFrequency = 0.1, .maxFrequency = 5.0}},  // mostly noise: many near maxima
  };
  for (const Case& c : cases) {
    std::vector<std::complex<double>> z;
    for (std::size_t i = 0; i < c.n; ++i) {
      const double t = static_cast<double>(i) * c.dt;
      const double im = c.search.bothSigns ? std::sin(2.0 * std::numbers::pi * c.f * t) + c.noise * noise(rng) : 0.0;
      z.emplace_back(std::cos(2.0 * std::numbers::pi * c.f * t) + c.noise * noise(rng) + 0.01 * t, im);
    }
    ToneSearch direct = c.search;
    direct.directSum = true;
    const Tone byFft = dominantTone(z, c.dt, c.search), bySum = dominantTone(z, c.dt, direct);
    EXPECT_EQ(byFft.found, bySum.found) << c.f;
    EXPECT_EQ(byFft.frequency, bySum.frequency) << c.f;
    EXPECT_EQ(byFft.amplitude, bySum.amplitude) << c.f;
    EXPECT_EQ(byFft.share, bySum.share) << c.f;
    EXPECT_EQ(byFft.samplesUsed, bySum.samplesUsed) << c.f;
    if (c.noise < 1.0) {
      EXPECT_NEAR(byFft.frequency, c.f, 0.01) << "the tone itself is found";
    }
  }
}

}  // namespace
}  // namespace hemiroll::analysis
