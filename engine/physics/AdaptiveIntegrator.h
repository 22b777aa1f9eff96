#pragma once
// Adaptive integrators: embedded Runge-Kutta pairs that choose their own step
// from an error estimate, and keep a dense output (a polynomial through the
// last accepted step) so that output grids and events are served by
// interpolation instead of by shortening or repeating steps.
//
// Tolerance: one number `tol`, used as both absolute and relative tolerance
// per component. A step is accepted when the RMS over the n components of
//   e_i / (tol + tol * max(|x_i(t)|, |x_i(t + h)|))
// is at most 1 (Hairer-Norsett-Wanner I, Sec. II.4, eq. 4.10, with
// atol = rtol = tol). The state mixes metres, radians and their rates, so the
// absolute part is in each slot's own SI unit; the states of this model are
// O(1e-2..1e1) in those units, so tol reads roughly as "relative error per
// unit time of the largest components".
//
// Step-size control: the PI controller of Gustafsson as written in Hairer &
// Wanner's DOPRI5 (HNW I, Sec. IV.2): h_new = h * safe * err^-a * err_old^b,
// a = 1/q - 0.75 b, with the growth limited to [1/5, 10] per step and no
// growth right after a rejection.
//
// Two ways to use one:
//  - as an Integrator<N> (step(system, t, x, h)): integrates from t to t + h
//    with as many internal steps as the tolerance needs, the last one ending
//    exactly at t + h; consecutive calls continue with the step size reached.
//  - step by step: start(), takeStep() (one accepted step), interpolate() on
//    the last accepted step. Stepper<N> uses this to follow an output grid and
//    to locate domain events on the dense output.

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/physics/Integrator.h"

namespace hemiroll::physics {

struct AdaptiveStatistics {
  long long evaluations = 0;  // right-hand side evaluations
  long long accepted = 0;     // accepted steps
  long long rejected = 0;     // rejected attempts
};

template <int N>
class AdaptiveIntegrator : public Integrator<N> {
 public:
  // Used until setTolerance is called: tight enough for play, loose enough to
  // be cheap (about the error of RK4 at 1 ms on the paper's scenes).
  static constexpr double kDefaultTolerance = 1e-8;

  AdaptiveIntegrator* adaptive() override { return this; }

  void setTolerance(double tol) { tol_ = tol; }
  double tolerance() const { return tol_; }
  const AdaptiveStatistics& statistics() const { return stats_; }
  void resetStatistics() { stats_ = {}; }

  // Restarts at (t0, x0): forgets the step size and the error history.
  void start(const OdeSystem<N>& f, double t0, const StateVector<N>& x0) {
    system_ = &f;
    begin_ = t0;
    restart(f, t0, x0);
    h_ = initialStepSize(f);
    logErrOld_ = std::log(1e-4);
    rejectedLast_ = false;
  }

  // One accepted step from time(), no longer than tLimit - time(). Returns
  // false (and leaves the state as it was) when the step size underflows,
  // which happens only at a singularity of the model or of its coordinates.
  bool takeStep(const OdeSystem<N>& f, double tLimit) {
    const double t = time();
    const double remaining = tLimit - t;
    if (!(remaining > 0.0)) return false;
    const double hMin = 16.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t));
    for (;;) {
      const bool clamped = h_ >= remaining;
      const double h = clamped ? remaining : h_;
      if (h < hMin && !clamped) return false;
      const double err = attempt(f, h);
      if (err <= 1.0) {
        accept(f);
        begin_ = t;
        ++stats_.accepted;
        double next = h * growth(err);
        if (rejectedLast_) next = std::min(next, h);
        // A step cut short to land on tLimit says nothing against the longer
        // step the controller had proposed.
        h_ = clamped ? std::max(next, h_) : next;
        logErrOld_ = std::log(std::max(err, 1e-4));
        rejectedLast_ = false;
        return true;
      }
      ++stats_.rejected;
      rejectedLast_ = true;
      // A non-finite error (a stage left the model's domain) shrinks by the
      // largest factor.
      h_ = h * (std::isfinite(err) ? std::max(kMinShrink, kSafety * std::pow(err, -exponent())) : kMinShrink);
      if (h_ < hMin) return false;
    }
  }

  // One step of exactly h, accepted whatever its error (returned): for
  // convergence studies and fixed grids. The step-size memory is untouched.
  double takeFixedStep(const OdeSystem<N>& f, double h) {
    const double t = time();
    const double err = attempt(f, h);
    accept(f);
    begin_ = t;
    ++stats_.accepted;
    return err;
  }

  double time() const { return end_; }
  double stepBegin() const { return begin_; }
  // The state at time() (the end of the last accepted step).
  virtual const StateVector<N>& state() const = 0;
  // The dense output on the last accepted step, at t in [stepBegin(), time()].
  virtual void interpolate(double t, StateVector<N>& x) = 0;

  // Integrates to tEnd exactly, in accepted steps; returns false on step-size
  // underflow (t and x are then where it stopped).
  bool advanceTo(const OdeSystem<N>& f, double& t, StateVector<N>& x, double tEnd) {
    if (system_ != &f || t != time() || x != state()) start(f, t, x);
    bool ok = true;
    while (time() < tEnd && (ok = takeStep(f, tEnd))) {
    }
    t = time();
    x = state();
    return ok;
  }

  // Integrator<N>: from t to t + h, the last internal step ending exactly there.
  void step(const OdeSystem<N>& f, double t, StateVector<N>& x, double h) override {
    double time = t;
    if (!advanceTo(f, time, x, t + h)) x.setConstant(std::numeric_limits<double>::quiet_NaN());
  }

 protected:
  // Sets the state to (t0, x0) and evaluates what the first step needs.
  virtual void restart(const OdeSystem<N>& f, double t0, const StateVector<N>& x0) = 0;
  // Computes a candidate step of length h from the current state and returns
  // its scaled error norm (<= 1 to accept; +inf if anything was non-finite).
  virtual double attempt(const OdeSystem<N>& f, double h) = 0;
  // Makes the last candidate the current state (time() moves to its end).
  virtual void accept(const OdeSystem<N>& f) = 0;
  // Order of the error estimate plus one (the q of the controller's exponent).
  virtual int controlOrder() const = 0;
  // The b of the PI controller (0 gives the classical I controller).
  virtual double controlBeta() const { return 0.04; }

  void countEvaluations(long long n) { stats_.evaluations += n; }
  void setTime(double t) { end_ = t; }

  // sk_i = tol + tol * max(|a_i|, |b_i|), the weights of the error norm.
  template <class A, class B>
  StateVector<N> errorWeights(const A& a, const B& b) const {
    return (tol_ + tol_ * a.cwiseAbs().cwiseMax(b.cwiseAbs()).array()).matrix();
  }

 private:
  static constexpr double kSafety = 0.9;
  static constexpr double kMinShrink = 0.2;  // at most 5x smaller per attempt
  static constexpr double kMaxGrowth = 10.0;

  double exponent() const { return 1.0 / controlOrder() - 0.75 * controlBeta(); }

  double growth(double err) const {
    if (err == 0.0) return kMaxGrowth;
    // err^-a * err_old^b as one exp of logs, the old one kept from the last
    // step: one log and one exp per step instead of two pow calls.
    const double g = kSafety * std::exp(controlBeta() * logErrOld_ - exponent() * std::log(err));
    return std::clamp(g, kMinShrink, kMaxGrowth);
  }

  // The starting step of HNW I, Sec. II.4 ("Starting step size"): a first
  // guess from |x| / |x'|, refined with a second derivative estimate, in the
  // norm of the error weights.
  double initialStepSize(const OdeSystem<N>& f) {
    const StateVector<N>& x0 = state();
    StateVector<N> f0;
    f.derivative(end_, x0, f0);
    const StateVector<N> sk = errorWeights(x0, x0);
    auto norm = [&](const StateVector<N>& v) { return std::sqrt(v.cwiseQuotient(sk).squaredNorm() / N); };
    const double d0 = norm(x0), d1 = norm(f0);
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    const StateVector<N> x1 = x0 + h0 * f0;
    StateVector<N> f1;
    f.derivative(end_ + h0, x1, f1);
    countEvaluations(2);
    const double d2 = norm(f1 - f0) / h0;
    const double d = std::max(d1, d2);
    const double h1 = d <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / d, 1.0 / controlOrder());
    const double h = std::min(100.0 * h0, h1);
    return std::isfinite(h) && h > 0.0 ? h : 1e-6;
  }

  const OdeSystem<N>* system_ = nullptr;
  double tol_ = kDefaultTolerance;
  double h_ = 0.0;
  double logErrOld_ = 0.0;  // log of the last accepted step's error norm
  bool rejectedLast_ = false;
  double begin_ = 0.0;
  double end_ = 0.0;
  AdaptiveStatistics stats_;
};

}  // namespace hemiroll::physics
