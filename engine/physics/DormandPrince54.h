#pragma once
// Dormand-Prince 5(4), "DOPRI5": the 7-stage embedded pair of Dormand &
// Prince 1980 (J. Comput. Appl. Math. 6, 19-26), propagating the 5th-order
// solution, with the 4th-order embedded solution as error estimate and
// first-same-as-last (the 7th stage is the next step's first). Dense output:
// the 4th-order continuous extension of Shampine 1986 (Math. Comp. 46,
// 135-150), written in the Hermite-like form of HNW I, Sec. II.6, which
// interpolates x and x' at both ends of the step.
// Tableau from HNW I, Table II.5.2 (typed from the published rationals).

#include "engine/physics/AdaptiveIntegrator.h"

namespace hemiroll::physics {

namespace dopri5 {
inline constexpr double c2 = 1.0 / 5.0, c3 = 3.0 / 10.0, c4 = 4.0 / 5.0, c5 = 8.0 / 9.0;
inline constexpr double a21 = 1.0 / 5.0;
inline constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
inline constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
inline constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                        a54 = -212.0 / 729.0;
inline constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                        a65 = -5103.0 / 18656.0;
// The 5th-order weights (also row 7 of A: FSAL).
inline constexpr double b1 = 35.0 / 384.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0, b5 = -2187.0 / 6784.0,
                        b6 = 11.0 / 84.0;
// b - b_hat: the difference of the 5th- and 4th-order weights.
inline constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                        e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
// Shampine's dense output coefficients (HNW I, Sec. II.6, eq. 6.12 ff.).
inline constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                        d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                        d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
}  // namespace dopri5

template <int N>
class DormandPrince54 final : public AdaptiveIntegrator<N> {
 public:
  std::string_view name() const override { return "dopri5"; }
  int order() const override { return 5; }
  const StateVector<N>& state() const override { return x_; }

  // x(t) = r1 + s (r2 + (1-s) (r3 + s (r4 + (1-s) r5))), s = (t - t0) / h.
  void interpolate(double t, StateVector<N>& x) override {
    if (!denseReady_) prepareDense();
    const double s = (t - this->stepBegin()) / hDone_, s1 = 1.0 - s;
    x = xPrev_ + s * (r2_ + s1 * (r3_ + s * (r4_ + s1 * r5_)));
  }

 protected:
  int controlOrder() const override { return 5; }

  void restart(const OdeSystem<N>& f, double t0, const StateVector<N>& x0) override {
    x_ = x0;
    this->setTime(t0);
    f.derivative(t0, x_, k1_);
    this->countEvaluations(1);
    denseReady_ = false;
    hDone_ = 0.0;
  }

  double attempt(const OdeSystem<N>& f, double h) override {
    using namespace dopri5;
    const double t = this->time();
    stage_ = x_ + h * (a21 * k1_);
    f.derivative(t + c2 * h, stage_, k2_);
    stage_ = x_ + h * (a31 * k1_ + a32 * k2_);
    f.derivative(t + c3 * h, stage_, k3_);
    stage_ = x_ + h * (a41 * k1_ + a42 * k2_ + a43 * k3_);
    f.derivative(t + c4 * h, stage_, k4_);
    stage_ = x_ + h * (a51 * k1_ + a52 * k2_ + a53 * k3_ + a54 * k4_);
    f.derivative(t + c5 * h, stage_, k5_);
    stage_ = x_ + h * (a61 * k1_ + a62 * k2_ + a63 * k3_ + a64 * k4_ + a65 * k5_);
    f.derivative(t + h, stage_, k6_);
    xNew_ = x_ + h * (b1 * k1_ + b3 * k3_ + b4 * k4_ + b5 * k5_ + b6 * k6_);
    f.derivative(t + h, xNew_, k7_);
    this->countEvaluations(6);
    hTry_ = h;
    const StateVector<N> error = h * (e1 * k1_ + e3 * k3_ + e4 * k4_ + e5 * k5_ + e6 * k6_ + e7 * k7_);
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
    denseReady_ = false;
  }

 private:
  // Built on the first interpolation in a step: a run that never asks for
  // output between steps does not pay for it.
  void prepareDense() {
    using namespace dopri5;
    const double h = hDone_;
    r2_ = x_ - xPrev_;
    r3_ = h * k1Prev_ - r2_;
    r4_ = r2_ - h * k1_ - r3_;
    r5_ = h * (d1 * k1Prev_ + d3 * k3_ + d4 * k4_ + d5 * k5_ + d6 * k6_ + d7 * k1_);
    denseReady_ = true;
  }

  StateVector<N> x_, xNew_, xPrev_, stage_;
  StateVector<N> k1_, k2_, k3_, k4_, k5_, k6_, k7_, k1Prev_;
  StateVector<N> r2_, r3_, r4_, r5_;
  double hTry_ = 0.0, hDone_ = 0.0;
  bool denseReady_ = false;
};

}  // namespace hemiroll::physics
