#pragma once
// Dormand-Prince 5(4), "DOPRI5": the 7-stage embedded pair of Dormand &
// Prince 1980 (J. Comput. Appl. Math. 6, 19-26), propagating the 5th-order
// solution, with the 4th-order embedded solution as error estimate and
// first-same-as-last (the 7th stage is the next step's first). Dense output:
// the 4th-order continuous extension of Shampine 1986 (Math. Comp. 46,
// 135-150), written in the Hermite-like form of HNW I, Sec. II.6, which
// interpolates x and x' at both ends of the step.
// Tableau from HNW I, Table II.5.2 (typed from the published rationals).

#include "engine/physics/EmbeddedPair54.h"

namespace hemiroll::physics {

// The tableau, for EmbeddedPair54.
struct Dopri5Tableau {
  static constexpr double c2 = 1.0 / 5.0, c3 = 3.0 / 10.0, c4 = 4.0 / 5.0, c5 = 8.0 / 9.0;
  static constexpr double a21 = 1.0 / 5.0;
  static constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
  static constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
  static constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                          a54 = -212.0 / 729.0;
  static constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                          a65 = -5103.0 / 18656.0;
  // The 5th-order weights (also row 7 of A: FSAL).
  static constexpr double b1 = 35.0 / 384.0, b2 = 0.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0, b5 = -2187.0 / 6784.0,
                          b6 = 11.0 / 84.0;
  // b - b_hat: the difference of the 5th- and 4th-order weights.
  static constexpr double e1 = 71.0 / 57600.0, e2 = 0.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                          e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
  // Shampine's dense output coefficients (HNW I, Sec. II.6, eq. 6.12 ff.).
  static constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                          d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                          d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
};

template <int N>
class DormandPrince54 final : public EmbeddedPair54<N, Dopri5Tableau> {
  using Base = EmbeddedPair54<N, Dopri5Tableau>;

 public:
  std::string_view name() const override { return "dopri5"; }

  // x(t) = r1 + s (r2 + (1-s) (r3 + s (r4 + (1-s) r5))), s = (t - t0) / h.
  void interpolate(double t, StateVector<N>& x) override {
    if (!denseReady_) prepareDense();
    const double s = (t - this->stepBegin()) / this->hDone_, s1 = 1.0 - s;
    x = this->xPrev_ + s * (r2_ + s1 * (r3_ + s * (r4_ + s1 * r5_)));
  }

 protected:
  void restart(const OdeSystem<N>& f, double t0, const StateVector<N>& x0) override {
    Base::restart(f, t0, x0);
    denseReady_ = false;
  }
  void accept(const OdeSystem<N>& f) override {
    Base::accept(f);
    denseReady_ = false;
  }

 private:
  // Built on the first interpolation in a step: a run that never asks for
  // output between steps does not pay for it.
  void prepareDense() {
    using T = Dopri5Tableau;
    const double h = this->hDone_;
    r2_ = this->x_ - this->xPrev_;
    r3_ = h * this->k1Prev_ - r2_;
    r4_ = r2_ - h * this->k1_ - r3_;
    r5_ = h * (T::d1 * this->k1Prev_ + T::d3 * this->k3_ + T::d4 * this->k4_ + T::d5 * this->k5_ +
               T::d6 * this->k6_ + T::d7 * this->k1_);
    denseReady_ = true;
  }

  StateVector<N> r2_, r3_, r4_, r5_;
  bool denseReady_ = false;
};

}  // namespace hemiroll::physics
