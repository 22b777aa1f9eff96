#pragma once
// What every explicit embedded pair here keeps between steps (DOPRI5, Tsit5,
// Vern7): the state, the derivative there (the next step's first stage), the
// last accepted step's start, first slope and length (for dense output), and
// the cubic Hermite interpolant that Tsit5 and Vern7 use as theirs. The
// steps themselves, and so their arithmetic, are each pair's own.

#include "engine/physics/AdaptiveIntegrator.h"

namespace hemiroll::physics {

template <int N>
class ExplicitPair : public AdaptiveIntegrator<N> {
 public:
  const StateVector<N>& state() const override { return x_; }

 protected:
  void restart(const OdeSystem<N>& f, double t0, const StateVector<N>& x0) override {
    x_ = x0;
    this->setTime(t0);
    f.derivative(t0, x_, k1_);
    this->countEvaluations(1);
    hDone_ = 0.0;
  }

  // Cubic Hermite on the last accepted step: through x and x' at both ends
  // (third order between the steps, exact at their ends).
  void hermite(double t, StateVector<N>& x) const {
    const double h = hDone_;
    const double s = (t - this->stepBegin()) / h, s2 = s * s, s3 = s2 * s;
    x = (2 * s3 - 3 * s2 + 1) * xPrev_ + (s3 - 2 * s2 + s) * h * k1Prev_ + (-2 * s3 + 3 * s2) * x_ +
        (s3 - s2) * h * k1_;
  }

  // x_ and k1_: the state and its derivative; xPrev_, k1Prev_, hDone_: the
  // last accepted step's start, first slope and length; xNew_, hTry_: the
  // attempt in progress; stage_: scratch.
  StateVector<N> x_, xNew_, xPrev_, stage_, k1_, k1Prev_;
  double hTry_ = 0.0, hDone_ = 0.0;
};

}  // namespace hemiroll::physics
