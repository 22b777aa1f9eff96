#pragma once
// A periodogram on a regular grid of frequencies by one FFT (FFTW3), for
// DominantTone: |sum_m z_m exp(-2 pi i f m dt)|^2 at f = start + k df,
// k = 0 .. count-1, where df = 1 / (fftLength dt). The negative side, f =
// -(start + k df), is the same grid for conj(z) (conjugating the sum
// conjugates each term), which is how DominantTone searches it: on the
// filter the positive side has just made. The direct sum costs
// (grid frequencies) x (samples), both growing with the recording: an hour
// at 100 Hz took 13 s and a day would take hours; the FFT costs
// fftLength log(fftLength).
//
// How: the samples are shifted by `start` (multiplied by exp(-2 pi i start
// m dt)); bin k of a transform of fftLength points is then the grid's k-th
// frequency. That transform is evaluated at its first `count` bins only, by
// Bluestein's chirp-z convolution with FFTs of a power of two (issue 32):
// FFTW planned a transform of an awkward length (4 x a prime, as a sweep's
// windows give) in ~3 ms, more than the sweep point's integration, and a
// sweep has as many lengths as points; the power-of-two plans are made once.
// The round-off differs from the direct sum's in the last bits (DominantTone
// uses these powers to find the peak and the direct sum for the values it
// reports). FFTW's planner is not thread-safe: plans are made under one lock
// (sweeps run tone searches on many threads); executing them is.

#include <complex>
#include <cstddef>
#include <span>

namespace hemiroll::analysis {

// `out` gets `count` powers; requires finite samples, samples.size() <=
// fftLength and count <= fftLength.
void fftGridPowers(std::span<const std::complex<double>> samples, double dt, std::size_t fftLength, double start,
                   std::size_t count, std::span<double> out);

}  // namespace hemiroll::analysis
