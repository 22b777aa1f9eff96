#pragma once
// The strongest periodic component of a sampled signal: the peak of its
// periodogram over a band of frequencies, and how clearly it stands out.
//
// The periodogram's grid is computed by FFT (Periodogram.h: n log n, where
// the direct sum over every grid frequency grew with the square of the
// recording's length); the three powers about the peak that the refinement
// uses, the refined peak's and any maximum within 1e-9 of the strongest are
// the direct sum's, so a Tone has the bits it had before the FFT.
//
// The signal is complex (x + i y of a planar path, or of its velocity), so a
// rotation has one frequency with a sign: positive for counter-clockwise.
// Real signals pass y = 0 and search positive frequencies only.
//
// The mean is removed and a Hann taper applied (its sidelobes fall fast,
// so a slow drift does not leak far into the band). The periodogram is
// evaluated on a grid `oversampling` times finer than 1 / T and the peak
// refined by a parabola through the three highest grid values. Only a local
// maximum inside the band counts: a maximum at the band's lower edge is the
// tail of something slower (a drift, a turning arc), not a tone.
//
// `share` says how clearly the tone stands out: its power (amplitude^2 for
// a complex exponential, amplitude^2 / 2 for a real cosine) over the
// signal's mean power about its mean. A pure tone gives 1; the paper's rose
// gives 0.98 on rho, a trochoid's loops 0.99 on the velocity.
// White noise spreads its power over N / 2 independent bins: the strongest
// holds about 1.5 ln(N) / N of it with the taper (< 0.01 for N >= 1000), and
// noise smoothed to a few hertz still spreads over T * (a few hertz) bins.

#include <complex>
#include <span>

namespace hemiroll::analysis {

struct ToneSearch {
  double minFrequency = 0.0;   // [Hz] lowest |f| searched (> 0 leaves out the drift)
  double maxFrequency = 5.0;   // [Hz] highest |f| searched (clamped to Nyquist)
  bool bothSigns = true;       // false: positive frequencies only (real signals)
  int oversampling = 4;
  // The periodogram by the direct sum over every grid frequency (the way
  // before the FFT, for tests and comparisons) instead of by FFT.
  bool directSum = false;
};

struct Tone {
  bool found = false;          // false: no band to search, or a signal without variation
  double frequency = 0.0;      // [Hz], signed
  double amplitude = 0.0;      // of the complex exponential (bothSigns), or of the cosine (real signals) [signal units]
  double share = 0.0;          // [0, 1] the tone's power over the signal's mean power about its mean
  std::size_t samplesUsed = 0; // the signal's length after block averaging (kMaxToneWork)
};

// A long, finely sampled signal (100k rows) is first averaged over blocks
// of k samples, the smallest k that brings (grid frequencies) x (samples)
// under this many steps and keeps the band below a quarter of the new
// sampling rate; shorter signals are used as they are. (The rule is from the
// direct sum's cost; kept so that features are what they were. Past the
// band's limit the signal's length, and the FFT's, grows with the
// recording's.)
inline constexpr double kMaxToneWork = 5e7;

Tone dominantTone(std::span<const std::complex<double>> signal, double dt, const ToneSearch& search);

// |sum_n z_n exp(-2 pi i f_k n dt)|^2 for each frequency f_k, into out[k]
// (the periodogram's values before scaling). Each power has the bits of the
// one-frequency sum by a rotating phasor (renormalised every 256 samples);
// several are computed side by side because one alone waits on its chain.
void periodogramPowers(std::span<const std::complex<double>> samples, std::span<const double> frequencies,
                       double dt, std::span<double> out);

}  // namespace hemiroll::analysis
