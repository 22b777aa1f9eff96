#include "engine/analysis/DominantTone.h"

#include "engine/analysis/Periodogram.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>


namespace hemiroll::analysis {

namespace {

// |sum_n w_n z_n exp(-2 pi i f n dt)|^2 for each of the K frequencies f, by
// rotating phasors (renormalised every 256 steps so that their moduli stay 1
// to round-off). Why K at once: one frequency's sum is a dependent chain of
// complex products, so the CPU waits on each; K independent chains in one
// pass over the samples keep it busy. Each chain does exactly the operations
// it would alone, so a power has the same bits whatever K.
//
// The products are written out in real arithmetic, (a + bi)(c + di) =
// (ac - bd) + (ad + bc)i, the very operations of the compiler's complex
// product, without its check for a NaN result (C Annex G's recovery of
// infinities), which cannot fire here: the samples are finite (dominantTone
// returns before this otherwise) and the phasors have modulus 1. Without the
// check's branches the K chains run side by side (tonePowers is 3x faster).
// kChains chains, two to an SSE2 register (every x86-64): a lane does exactly
// the scalar operations of its chain.
typedef double ChainPair __attribute__((vector_size(16)));
constexpr std::size_t kPairs = 4;
constexpr std::size_t kChains = 2 * kPairs;

// Pairs: how many of the kPairs registers carry chains (a search's last
// power is one frequency: one pair, not four, goes over the samples).
template <std::size_t Pairs>
void tonePowersIn(std::span<const std::complex<double>> tapered, const double* f, std::size_t count, double dt,
                  double* out) {
  ChainPair rotRe[Pairs] = {}, rotIm[Pairs] = {}, re[Pairs] = {}, im[Pairs] = {}, sumRe[Pairs] = {},
            sumIm[Pairs] = {};
  for (std::size_t k = 0; k < count; ++k) {
    const double step = -2.0 * std::numbers::pi * f[k] * dt;
    rotRe[k / 2][k % 2] = std::cos(step);
    rotIm[k / 2][k % 2] = std::sin(step);
    re[k / 2][k % 2] = 1.0;
  }
  for (std::size_t n = 0; n < tapered.size(); ++n) {
    const double zRe = tapered[n].real(), zIm = tapered[n].imag();
    for (std::size_t p = 0; p < Pairs; ++p) {
      sumRe[p] += zRe * re[p] - zIm * im[p];
      sumIm[p] += zRe * im[p] + zIm * re[p];
      const ChainPair nextRe = re[p] * rotRe[p] - im[p] * rotIm[p];
      im[p] = re[p] * rotIm[p] + im[p] * rotRe[p];
      re[p] = nextRe;
    }
    if ((n & 255u) == 255u) {
      for (std::size_t k = 0; k < count; ++k) {
        const double modulus = std::abs(std::complex<double>(re[k / 2][k % 2], im[k / 2][k % 2]));
        re[k / 2][k % 2] /= modulus;
        im[k / 2][k % 2] /= modulus;
      }
    }
  }
  for (std::size_t k = 0; k < count; ++k)
    out[k] = std::norm(std::complex<double>(sumRe[k / 2][k % 2], sumIm[k / 2][k % 2]));
}

void tonePowers(std::span<const std::complex<double>> tapered, const double* f, std::size_t count, double dt,
                double* out) {
  static_assert(kPairs == 4);
  switch ((count + 1) / 2) {
    case 0: return;
    case 1: return tonePowersIn<1>(tapered, f, count, dt, out);
    case 2: return tonePowersIn<2>(tapered, f, count, dt, out);
    case 3: return tonePowersIn<3>(tapered, f, count, dt, out);
    default: return tonePowersIn<4>(tapered, f, count, dt, out);
  }
}

double power(std::span<const std::complex<double>> tapered, double f, double dt) {
  double out;
  tonePowers(tapered, &f, 1, dt, &out);
  return out;
}

}  // namespace

void periodogramPowers(std::span<const std::complex<double>> samples, std::span<const double> frequencies, double dt,
                       std::span<double> out) {
  for (std::size_t i = 0; i < frequencies.size(); i += kChains)
    tonePowers(samples, &frequencies[i], std::min(kChains, frequencies.size() - i), dt, &out[i]);
}

namespace {

// Relative difference under which two maxima of the FFT's periodogram are
// told apart by the direct sum: far above the FFT's round-off (1e-15 x
// log N), far below any difference between real peaks.
constexpr double kNearTie = 1e-9;

// The strongest interior local maximum (neighbours on the same grid, both
// lower); freqs.size() when there is none.
std::size_t strongestInteriorMaximum(const std::vector<double>& freqs, const std::vector<double>& powers, double df) {
  std::size_t best = freqs.size();
  for (std::size_t i = 1; i + 1 < freqs.size(); ++i) {
    const bool neighbours = std::abs(freqs[i + 1] - freqs[i - 1] - 2.0 * df) < 1e-9 * df;
    if (neighbours && powers[i] > powers[i - 1] && powers[i] >= powers[i + 1] &&
        (best == freqs.size() || powers[i] > powers[best]))
      best = i;
  }
  return best;
}

// Averages of consecutive blocks of k samples (the last, shorter block
// dropped): a boxcar low-pass and resampling in one.
std::vector<std::complex<double>> blockAverages(std::span<const std::complex<double>> signal, std::size_t k) {
  std::vector<std::complex<double>> out(signal.size() / k);
  for (std::size_t b = 0; b < out.size(); ++b) {
    std::complex<double> sum(0.0, 0.0);
    for (std::size_t i = 0; i < k; ++i) sum += signal[b * k + i];
    out[b] = sum / static_cast<double>(k);
  }
  return out;
}

// The block length for kMaxToneWork (1: none needed).
std::size_t blockLength(std::size_t n, double dt, const ToneSearch& search) {
  const double duration = dt * static_cast<double>(n);
  const double band = std::min(search.maxFrequency, 0.5 / dt) - std::max(search.minFrequency, 0.0);
  const double frequencies = band * duration * std::max(search.oversampling, 1) * (search.bothSigns ? 2.0 : 1.0);
  if (!(frequencies * static_cast<double>(n) > kMaxToneWork)) return 1;
  const auto byWork = static_cast<std::size_t>(std::ceil(frequencies * static_cast<double>(n) / kMaxToneWork));
  // The band's top stays below a quarter of the averaged sampling rate.
  const auto byBand = static_cast<std::size_t>(std::floor(1.0 / (4.0 * search.maxFrequency * dt)));
  return std::max<std::size_t>(1, std::min(byWork, byBand));
}

// The signal less its mean under a Hann taper, with what the amplitude and
// the share need: the taper's sum and the untapered variance.
struct TaperedSignal {
  std::vector<std::complex<double>> samples;
  std::complex<double> mean;
  double taperSum = 0.0, variance = 0.0;
};

// The Hann weights of n samples, kept for the next search of the same
// length: a sweep point's rose and helix searches are over one window (a cos
// per sample had been 3 % of a point's analysis).
const std::vector<double>& hannWeights(std::size_t n) {
  thread_local std::vector<double> weights;
  if (weights.size() != n) {
    weights.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      weights[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (static_cast<double>(i) + 0.5) / static_cast<double>(n));
  }
  return weights;
}

TaperedSignal taperedSignal(std::span<const std::complex<double>> signal) {
  const std::size_t n = signal.size();
  TaperedSignal t;
  std::complex<double> sumZ(0.0, 0.0);
  for (const auto& z : signal) sumZ += z;
  t.mean = sumZ / static_cast<double>(n);
  t.samples.resize(n);
  const std::vector<double>& hann = hannWeights(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double w = hann[i];
    t.samples[i] = w * (signal[i] - t.mean);
    t.taperSum += w;
    t.variance += std::norm(signal[i] - t.mean);
  }
  return t;
}

// Grid: +fMin .. +fMax (steps + 1 frequencies df apart), and the same
// negated when both signs are searched; sorted. fMin + k df does not
// decrease with k (fMin >= 0), so the sorted grid is the negated side from
// its highest |f| down, then the positive side in order (written so instead
// of sorted: the sort had been 1 % of a sweep point's analysis).
std::vector<double> frequencyGrid(double fMin, double df, std::size_t steps, bool bothSigns) {
  std::vector<double> positive(steps + 1);
  for (std::size_t k = 0; k <= steps; ++k) positive[k] = fMin + static_cast<double>(k) * df;
  if (!bothSigns) return positive;
  std::vector<double> freqs;
  freqs.reserve(2 * positive.size());
  for (std::size_t k = positive.size(); k-- > 0;)
    if (positive[k] > 0.0) freqs.push_back(-positive[k]);
  freqs.insert(freqs.end(), positive.begin(), positive.end());
  return freqs;
}

// By FFT (Periodogram.h): the grid is fMin + k df on each side, and
// df = 1 / (oversampling T) makes it the bins of a transform of
// oversampling x n points. Sorted, the negative side comes first,
// highest |f| first.
void fftPowers(std::span<const std::complex<double>> tapered, double dt, const ToneSearch& search, double fMin,
               std::size_t steps, std::vector<double>& powers) {
  const std::size_t fftLength = static_cast<std::size_t>(std::max(search.oversampling, 1)) * tapered.size();
  std::vector<double> side(steps + 1);
  fftGridPowers(tapered, dt, fftLength, fMin, steps + 1, side);
  const std::size_t negatives = powers.size() - (steps + 1);
  for (std::size_t k = 0; k <= steps; ++k) powers[negatives + k] = side[k];
  if (negatives > 0) {
    // The negative side as the positive side of the conjugate (Periodogram.h),
    // on the filter the positive side has just made.
    std::vector<std::complex<double>> conjugate(tapered.size());
    for (std::size_t m = 0; m < tapered.size(); ++m) conjugate[m] = std::conj(tapered[m]);
    fftGridPowers(conjugate, dt, fftLength, fMin, steps + 1, side);
    const std::size_t first = fMin > 0.0 ? 0 : 1;  // f = 0 is on the positive side only
    for (std::size_t k = first; k <= steps; ++k) powers[negatives - 1 - (k - first)] = side[k];
  }
}

// The FFT's powers differ from the direct sum's in their last bits: where
// maxima are that close to the best, the direct sum decides, as it always
// did. Returns the strongest maximum then (freqs.size(): none).
std::size_t settleNearTies(std::span<const std::complex<double>> tapered, double dt, double df,
                           const std::vector<double>& freqs, std::vector<double>& powers, std::size_t best) {
  const double top = powers[best];
  std::vector<std::size_t> close;
  for (std::size_t i = 1; i + 1 < freqs.size(); ++i)
    if (powers[i] >= top * (1.0 - kNearTie)) close.push_back(i);
  // Each maximum and its two neighbours, all in one pass over the samples
  // (a pass per frequency had been 3 of the 4 passes of a search's direct
  // sums): a power has the same bits whatever the frequencies beside it.
  std::vector<std::size_t> at;
  for (std::size_t i : close)
    for (std::size_t j : {i - 1, i, i + 1})
      if (at.empty() || at.back() < j) at.push_back(j);
  std::vector<double> f(at.size()), p(at.size());
  for (std::size_t m = 0; m < at.size(); ++m) f[m] = freqs[at[m]];
  periodogramPowers(tapered, f, dt, p);
  for (std::size_t m = 0; m < at.size(); ++m) powers[at[m]] = p[m];
  return strongestInteriorMaximum(freqs, powers, df);
}

}  // namespace

Tone dominantTone(std::span<const std::complex<double>> signal, double dt, const ToneSearch& search) {
  if (const std::size_t k = blockLength(signal.size(), dt, search); k > 1) {
    const std::vector<std::complex<double>> averaged = blockAverages(signal, k);
    return dominantTone(averaged, dt * static_cast<double>(k), search);
  }
  Tone tone;
  const std::size_t n = signal.size();
  tone.samplesUsed = n;
  if (n < 8 || !(dt > 0.0)) return tone;
  const double duration = dt * static_cast<double>(n);
  const double fMax = std::min(search.maxFrequency, 0.5 / dt);
  const double fMin = std::max(search.minFrequency, 0.0);
  const double df = 1.0 / (duration * std::max(search.oversampling, 1));
  if (!(fMax > fMin + 2.0 * df)) return tone;

  const TaperedSignal t = taperedSignal(signal);
  const std::vector<std::complex<double>>& tapered = t.samples;
  // A constant signal (a still point, a straight line's velocity) has no
  // tone: its variance is round-off of the mean.
  const double roundOff = 1e-24 * (std::norm(t.mean) + 1e-300) * static_cast<double>(n);
  if (!(t.variance > roundOff) || !std::isfinite(t.variance)) return tone;

  const auto steps = static_cast<std::size_t>(std::floor((fMax - fMin) / df));
  const std::vector<double> freqs = frequencyGrid(fMin, df, steps, search.bothSigns);
  std::vector<double> powers(freqs.size());
  if (search.directSum)
    periodogramPowers(tapered, freqs, dt, powers);
  else
    fftPowers(tapered, dt, search, fMin, steps, powers);
  std::size_t best = strongestInteriorMaximum(freqs, powers, df);
  if (best == freqs.size()) return tone;
  if (!search.directSum) {
    best = settleNearTies(tapered, dt, df, freqs, powers, best);
    if (best == freqs.size()) return tone;
  }
  double f = freqs[best], peak = powers[best];
  const double a = powers[best - 1], b = powers[best], c = powers[best + 1];
  const double den = a - 2.0 * b + c;
  if (den < 0.0) {
    const double shift = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
    f += shift * df;
    peak = std::max(peak, power(tapered, f, dt));
  }
  tone.found = true;
  tone.frequency = f;
  // A real signal's cosine splits into +f and -f: its amplitude is twice the
  // exponential's and it holds a share of A^2 / 2 of the power.
  const double exponential = std::sqrt(peak) / t.taperSum;
  const double meanPower = t.variance / static_cast<double>(n);
  tone.amplitude = search.bothSigns ? exponential : 2.0 * exponential;
  tone.share = std::min(1.0, (search.bothSigns ? 1.0 : 2.0) * exponential * exponential / meanPower);
  return tone;
}

}  // namespace hemiroll::analysis
