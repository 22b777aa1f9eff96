#include "engine/analysis/Periodogram.h"

#include <fftw3.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>

namespace hemiroll::analysis {

namespace {

std::mutex& plannerLock() {
  static std::mutex lock;
  return lock;
}

struct FftwFree {
  void operator()(fftw_complex* p) const { fftw_free(p); }
};

}  // namespace

void fftGridPowers(std::span<const std::complex<double>> samples, double dt, std::size_t fftLength, double start,
                   int sign, std::size_t count, std::span<double> out) {
  const std::unique_ptr<fftw_complex[], FftwFree> buffer(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * fftLength)));
  fftw_plan plan = nullptr;
  {
    // FFTW_ESTIMATE: the plan is chosen by rule, not by timing, and the
    // buffer is not touched while planning.
    const std::lock_guard<std::mutex> guard(plannerLock());
    plan = fftw_plan_dft_1d(static_cast<int>(fftLength), buffer.get(), buffer.get(),
                            sign > 0 ? FFTW_FORWARD : FFTW_BACKWARD, FFTW_ESTIMATE);
  }
  // The shift that puts `start` on bin 0: exp(-2 pi i sign start m dt).
  const double turn = -2.0 * std::numbers::pi * (sign > 0 ? 1.0 : -1.0) * start * dt;
  for (std::size_t m = 0; m < fftLength; ++m) {
    std::complex<double> z(0.0, 0.0);
    if (m < samples.size()) z = samples[m] * std::polar(1.0, turn * static_cast<double>(m));
    buffer[m][0] = z.real();
    buffer[m][1] = z.imag();
  }
  fftw_execute(plan);
  for (std::size_t k = 0; k < count; ++k) out[k] = buffer[k][0] * buffer[k][0] + buffer[k][1] * buffer[k][1];
  const std::lock_guard<std::mutex> guard(plannerLock());
  fftw_destroy_plan(plan);
}

}  // namespace hemiroll::analysis
