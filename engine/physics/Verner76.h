#pragma once
// Verner's "most efficient" 7(6) pair: J. H. Verner, "Numerically optimal
// Runge-Kutta pairs with interpolants", Numer. Algorithms 53 (2010) 383-396,
// the 10-stage pair whose coefficients Verner publishes as
// RKV76.IIa.Efficient.00001675585.081206 (sfu.ca/~jverner), rounded to
// double. It propagates the 7th-order solution and estimates the error with
// the embedded 6th-order one. Not first-same-as-last: the derivative at the
// end of an accepted step is evaluated once, and serves both the next step's
// first stage and the dense output. tests/physics/Verner76Test.cpp checks the
// typed tableau against all 85 order conditions up to the 7th (the embedded
// weights against the 37 up to the 6th).
//
// Measured in docs/WORK_PRECISION.md: the fastest of ours on the heavy rose
// from 1e-4 to 1e-9 and on free motion at 1e-4 and 1e-5; Verner98.h at the
// tightest errors, DOP853 elsewhere.
//
// Dense output: the cubic Hermite interpolant of Tsitouras54.h (third order
// between the steps, exact at their ends), not Verner's 16-stage interpolant.

#include "engine/physics/ExplicitPair.h"

namespace hemiroll::physics {

struct Vern7Tableau {
  // As printed to 17 significant digits (each names one double).
  static constexpr double c2 = 5.0000000000000001e-03, c3 = 1.0888888888888888e-01, c4 = 1.6333333333333333e-01,
                          c5 = 4.5550000000000002e-01, c6 = 6.0950944899783810e-01, c7 = 8.8400000000000001e-01,
                          c8 = 9.2500000000000004e-01;  // c9 = c10 = 1
  static constexpr double a21 = 5.0000000000000001e-03;
  static constexpr double a31 = -1.0767901234567900e+00, a32 = 1.1856790123456791e+00;
  // a_i2 = 0 from row 4 on.
  static constexpr double a41 = 4.0833333333333333e-02, a43 = 1.2250000000000000e-01;
  static constexpr double a51 = 6.3891392362557264e-01, a53 = -2.4556726382236569e+00, a54 = 2.2722587145980842e+00;
  static constexpr double a61 = -2.6615773750187572e+00, a63 = 1.0804513886456137e+01, a64 = -8.3539146573961993e+00,
                          a65 = 8.2048759495665702e-01;
  static constexpr double a71 = 6.0677414346967709e+00, a73 = -2.4711273635911084e+01, a74 = 2.0427517930788895e+01,
                          a75 = -1.9061579788166472e+00, a76 = 1.0061722492420679e+00;
  static constexpr double a81 = 1.2054670076253203e+01, a83 = -4.9754784950468988e+01, a84 = 4.1142888638604674e+01,
                          a85 = -4.4617601499740038e+00, a86 = 2.0423348222391748e+00, a87 = -9.8348436654061080e-02;
  static constexpr double a91 = 1.0138146522881808e+01, a93 = -4.2641136031717501e+01, a94 = 3.5763840039922570e+01,
                          a95 = -4.3480228403929075e+00, a96 = 2.0098622683770357e+00, a97 = 3.4874904603382723e-01,
                          a98 = -2.7143900510483127e-01;
  static constexpr double a101 = -4.5030072034298676e+01, a103 = 1.8732724376545889e+02,
                          a104 = -1.5402882369350186e+02, a105 = 1.8564653063475362e+01,
                          a106 = -7.1418096792950791e+00, a107 = 1.3088085781613785e+00;
  // The 7th-order weights (b2 = b3 = b10 = 0).
  static constexpr double b1 = 4.7155618486272220e-02, b4 = 2.5750564298434153e-01, b5 = 2.6216653977412618e-01,
                          b6 = 1.5216092656738558e-01, b7 = 4.9399691700324844e-01, b8 = -2.9430311714032503e-01,
                          b9 = 8.1317472324951096e-02;
  // The 6th-order weights (bHat2 = bHat3 = bHat8 = bHat9 = 0).
  static constexpr double bHat1 = 4.4608606606341174e-02, bHat4 = 2.6716403785713727e-01,
                          bHat5 = 2.2010183001772929e-01, bHat6 = 2.1884317031431569e-01,
                          bHat7 = 2.2898717054112028e-01, bHat10 = 2.0295184663356284e-02;
};

template <int N>
class Verner76 final : public ExplicitPair<N> {
 public:
  std::string_view name() const override { return "vern7"; }
  int order() const override { return 7; }
  void interpolate(double t, StateVector<N>& x) override { this->hermite(t, x); }

 protected:
  using ExplicitPair<N>::x_;
  using ExplicitPair<N>::xNew_;
  using ExplicitPair<N>::xPrev_;
  using ExplicitPair<N>::stage_;
  using ExplicitPair<N>::k1_;
  using ExplicitPair<N>::k1Prev_;
  using ExplicitPair<N>::hTry_;
  using ExplicitPair<N>::hDone_;

  int controlOrder() const override { return 7; }

  double attempt(const OdeSystem<N>& f, double h) override {
    using T = Vern7Tableau;
    const double t = this->time();
    stage_ = x_ + h * (T::a21 * k1_);
    f.derivative(t + T::c2 * h, stage_, k2_);
    stage_ = x_ + h * (T::a31 * k1_ + T::a32 * k2_);
    f.derivative(t + T::c3 * h, stage_, k3_);
    stage_ = x_ + h * (T::a41 * k1_ + T::a43 * k3_);
    f.derivative(t + T::c4 * h, stage_, k4_);
    stage_ = x_ + h * (T::a51 * k1_ + T::a53 * k3_ + T::a54 * k4_);
    f.derivative(t + T::c5 * h, stage_, k5_);
    stage_ = x_ + h * (T::a61 * k1_ + T::a63 * k3_ + T::a64 * k4_ + T::a65 * k5_);
    f.derivative(t + T::c6 * h, stage_, k6_);
    stage_ = x_ + h * (T::a71 * k1_ + T::a73 * k3_ + T::a74 * k4_ + T::a75 * k5_ + T::a76 * k6_);
    f.derivative(t + T::c7 * h, stage_, k7_);
    stage_ = x_ + h * (T::a81 * k1_ + T::a83 * k3_ + T::a84 * k4_ + T::a85 * k5_ + T::a86 * k6_ + T::a87 * k7_);
    f.derivative(t + T::c8 * h, stage_, k8_);
    stage_ = x_ + h * (T::a91 * k1_ + T::a93 * k3_ + T::a94 * k4_ + T::a95 * k5_ + T::a96 * k6_ + T::a97 * k7_ +
                       T::a98 * k8_);
    f.derivative(t + h, stage_, k9_);
    stage_ = x_ + h * (T::a101 * k1_ + T::a103 * k3_ + T::a104 * k4_ + T::a105 * k5_ + T::a106 * k6_ +
                       T::a107 * k7_);
    f.derivative(t + h, stage_, k10_);
    this->countEvaluations(9);
    xNew_ = x_ + h * (T::b1 * k1_ + T::b4 * k4_ + T::b5 * k5_ + T::b6 * k6_ + T::b7 * k7_ + T::b8 * k8_ +
                      T::b9 * k9_);
    hTry_ = h;
    const StateVector<N> error =
        h * ((T::b1 - T::bHat1) * k1_ + (T::b4 - T::bHat4) * k4_ + (T::b5 - T::bHat5) * k5_ +
             (T::b6 - T::bHat6) * k6_ + (T::b7 - T::bHat7) * k7_ + T::b8 * k8_ + T::b9 * k9_ - T::bHat10 * k10_);
    const double err = std::sqrt(error.cwiseQuotient(this->errorWeights(x_, xNew_)).squaredNorm() / N);
    return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
  }

  void accept(const OdeSystem<N>& f) override {
    xPrev_ = x_;
    x_ = xNew_;
    k1Prev_ = k1_;
    hDone_ = hTry_;
    this->setTime(this->time() + hTry_);
    f.derivative(this->time(), x_, k1_);  // the next step's first stage and this one's end slope
    this->countEvaluations(1);
  }

 private:
  StateVector<N> k2_, k3_, k4_, k5_, k6_, k7_, k8_, k9_, k10_;
};

}  // namespace hemiroll::physics
