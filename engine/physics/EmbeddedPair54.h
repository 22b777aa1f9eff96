#pragma once
// The step of a seven-stage, first-same-as-last 5(4) Runge-Kutta pair, for
// any tableau of that shape (DormandPrince54.h, Tsitouras54.h): the stages,
// the 5th-order solution that is propagated, the error estimate from the
// weights' difference e = b - b_hat, and the seventh stage kept as the next
// step's first. What differs between the pairs, their coefficients and their
// dense output, is the tableau's and the derived class's.
//
// Tableau: constexpr c2..c5, a21..a65, b1..b6 and e1..e7 (b2, e2 may be 0:
// DOPRI5's are, and their terms are then left out, so that its arithmetic is
// the same operations in the same order as when it was written alone).

#include "engine/physics/ExplicitPair.h"

namespace hemiroll::physics {

template <int N, class Tableau>
class EmbeddedPair54 : public ExplicitPair<N> {
 public:
  int order() const override { return 5; }

 protected:
  using ExplicitPair<N>::x_;
  using ExplicitPair<N>::xNew_;
  using ExplicitPair<N>::xPrev_;
  using ExplicitPair<N>::stage_;
  using ExplicitPair<N>::k1_;
  using ExplicitPair<N>::k1Prev_;
  using ExplicitPair<N>::hTry_;
  using ExplicitPair<N>::hDone_;

  int controlOrder() const override { return 5; }

  double attempt(const OdeSystem<N>& f, double h) override {
    using T = Tableau;
    const double t = this->time();
    stage_ = x_ + h * (T::a21 * k1_);
    f.derivative(t + T::c2 * h, stage_, k2_);
    stage_ = x_ + h * (T::a31 * k1_ + T::a32 * k2_);
    f.derivative(t + T::c3 * h, stage_, k3_);
    stage_ = x_ + h * (T::a41 * k1_ + T::a42 * k2_ + T::a43 * k3_);
    f.derivative(t + T::c4 * h, stage_, k4_);
    stage_ = x_ + h * (T::a51 * k1_ + T::a52 * k2_ + T::a53 * k3_ + T::a54 * k4_);
    f.derivative(t + T::c5 * h, stage_, k5_);
    stage_ = x_ + h * (T::a61 * k1_ + T::a62 * k2_ + T::a63 * k3_ + T::a64 * k4_ + T::a65 * k5_);
    f.derivative(t + h, stage_, k6_);
    if constexpr (T::b2 != 0.0)
      xNew_ = x_ + h * (T::b1 * k1_ + T::b2 * k2_ + T::b3 * k3_ + T::b4 * k4_ + T::b5 * k5_ + T::b6 * k6_);
    else
      xNew_ = x_ + h * (T::b1 * k1_ + T::b3 * k3_ + T::b4 * k4_ + T::b5 * k5_ + T::b6 * k6_);
    f.derivative(t + h, xNew_, k7_);
    this->countEvaluations(6);
    hTry_ = h;
    StateVector<N> error;
    if constexpr (T::e2 != 0.0)
      error = h * (T::e1 * k1_ + T::e2 * k2_ + T::e3 * k3_ + T::e4 * k4_ + T::e5 * k5_ + T::e6 * k6_ + T::e7 * k7_);
    else
      error = h * (T::e1 * k1_ + T::e3 * k3_ + T::e4 * k4_ + T::e5 * k5_ + T::e6 * k6_ + T::e7 * k7_);
    const double err = std::sqrt(error.cwiseQuotient(this->errorWeights(x_, xNew_)).squaredNorm() / N);
    return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
  }

  void accept(const OdeSystem<N>&) override {
    xPrev_ = x_;
    x_ = xNew_;
    k1Prev_ = k1_;
    k1_ = k7_;  // first same as last
    hDone_ = hTry_;
    this->setTime(this->time() + hTry_);
  }

  // For the derived class's dense output, besides ExplicitPair's: the
  // accepted step's inner stages.
  StateVector<N> k2_, k3_, k4_, k5_, k6_, k7_;
};

}  // namespace hemiroll::physics
