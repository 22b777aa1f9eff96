#pragma once
// Gauss-Legendre collocation, the implicit Runge-Kutta methods with s stages
// and order 2s (Butcher 1964; HNW I, Sec. II.7, Table 7.4 for s = 2, 3).
// They are symmetric and symplectic: on reversible problems such as free
// rolling or an undamped tether the energy error stays bounded instead of
// drifting (HNW "Geometric Numerical Integration", Ch. X-XI), which is what a
// long run needs. Fixed step.
//
// The stage equations Z_i = h sum_j a_ij f(t + c_j h, x + Z_j) are solved by
// fixed-point iteration (GNI, Sec. VIII.6), converged to round-off: iterate
// until the update stops shrinking (or is zero), so the method's symmetry is
// not spoiled by a loose tolerance. The starting guess extrapolates the last
// step's collocation polynomial (GNI, Sec. VIII.6.1), which saves about half
// of the iterations when steps follow each other. The iteration converges for
// h L < 1 roughly (L the Lipschitz constant; here the fastest rocking or
// coupling rate), ~0.1 at the paper's 1 ms.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "engine/physics/Integrator.h"

namespace hemiroll::physics {

namespace gauss_legendre {

template <int S>
struct Tableau;

// sqrt(3) = 1.7320508075688772935..., nodes 1/2 -+ sqrt(3)/6.
template <>
struct Tableau<2> {
  static constexpr double r3 = 1.7320508075688772935274463415059;
  static constexpr std::array<double, 2> c{0.5 - r3 / 6.0, 0.5 + r3 / 6.0};
  static constexpr std::array<double, 2> b{0.5, 0.5};
  static constexpr std::array<std::array<double, 2>, 2> a{{{0.25, 0.25 - r3 / 6.0}, {0.25 + r3 / 6.0, 0.25}}};
};

// sqrt(15) = 3.8729833462074168852..., nodes 1/2 - sqrt(15)/10, 1/2, 1/2 + sqrt(15)/10.
template <>
struct Tableau<3> {
  static constexpr double r15 = 3.8729833462074168851792653997824;
  static constexpr std::array<double, 3> c{0.5 - r15 / 10.0, 0.5, 0.5 + r15 / 10.0};
  static constexpr std::array<double, 3> b{5.0 / 18.0, 4.0 / 9.0, 5.0 / 18.0};
  static constexpr std::array<std::array<double, 3>, 3> a{{
      {5.0 / 36.0, 2.0 / 9.0 - r15 / 15.0, 5.0 / 36.0 - r15 / 30.0},
      {5.0 / 36.0 + r15 / 24.0, 2.0 / 9.0, 5.0 / 36.0 - r15 / 24.0},
      {5.0 / 36.0 + r15 / 30.0, 2.0 / 9.0 + r15 / 15.0, 5.0 / 36.0},
  }};
};

}  // namespace gauss_legendre

template <int N, int S>
class GaussLegendre final : public Integrator<N> {
  using T = gauss_legendre::Tableau<S>;

 public:
  // A guard, not a tolerance: at 1 ms the iteration stalls at round-off after
  // 8-14 sweeps. Hitting the cap means h L is near 1 and the step is not to
  // be trusted; the statistics below count it.
  static constexpr int kMaxIterations = 60;

  GaussLegendre() {
    // Extrapolation weights: the last step's collocation polynomial u with
    // u(0) = 0, u(c_j) = Z_j (degree S), evaluated at 1 + c_i, minus u(1):
    // the guess for the new Z_i relative to the new starting point.
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) extrapolate_[i][j] = lagrange(j, 1.0 + T::c[i]) - lagrange(j, 1.0);
  }

  std::string_view name() const override { return S == 2 ? "gauss2" : "gauss3"; }
  int order() const override { return 2 * S; }

  void step(const OdeSystem<N>& f, double t, StateVector<N>& x, double h) override {
    // Only a guess: callers that snap t to a grid (t = i dt) still continue.
    const bool continues = haveLast_ && std::abs(t - lastEnd_) <= 1e-12 * std::max(1.0, std::abs(t)) &&
                           std::abs(h - lastH_) <= 1e-12 * h && x == lastX_ && &f == lastSystem_;
    if (continues) {
      for (int i = 0; i < S; ++i) {
        guess_[i].setZero();
        for (int j = 0; j < S; ++j) guess_[i] += extrapolate_[i][j] * z_[j];
      }
      for (int i = 0; i < S; ++i) z_[i] = guess_[i];
    } else {
      f.derivative(t, x, k_[0]);
      ++evaluations_;
      for (int i = 0; i < S; ++i) z_[i] = (T::c[i] * h) * k_[0];
    }

    double previous = std::numeric_limits<double>::infinity();
    for (int iteration = 0;; ++iteration) {
      for (int j = 0; j < S; ++j) {
        stage_ = x + z_[j];
        f.derivative(t + T::c[j] * h, stage_, k_[j]);
      }
      evaluations_ += S;
      double change = 0.0;
      for (int i = 0; i < S; ++i) {
        guess_[i] = (h * T::a[i][0]) * k_[0];
        for (int j = 1; j < S; ++j) guess_[i] += (h * T::a[i][j]) * k_[j];
        change = std::max(change, (guess_[i] - z_[i]).cwiseAbs().maxCoeff());
        z_[i] = guess_[i];
      }
      ++iterations_;
      // Converged to round-off: no change, or the change stopped shrinking.
      // (A NaN change compares false and ends at the cap; x becomes non-finite
      // and the stepper reports it.)
      if (change == 0.0 || change >= previous || iteration + 1 >= kMaxIterations) {
        if (iteration + 1 >= kMaxIterations) ++capped_;
        break;
      }
      previous = change;
    }
    // The k_ are f at the stages of the last-but-one sweep's Z, which agree
    // with the converged Z to round-off.
    increment_ = (h * T::b[0]) * k_[0];
    for (int j = 1; j < S; ++j) increment_ += (h * T::b[j]) * k_[j];
    x += increment_;
    haveLast_ = true;
    lastEnd_ = t + h;
    lastH_ = h;
    lastX_ = x;
    lastSystem_ = &f;
  }

  long long evaluations() const { return evaluations_; }
  long long iterations() const { return iterations_; }
  long long cappedSteps() const { return capped_; }

 private:
  // The Lagrange basis polynomial of node c_j over the nodes {0, c_1..c_S}.
  static double lagrange(int j, double s) {
    double value = (s - 0.0) / (T::c[j] - 0.0);
    for (int m = 0; m < S; ++m)
      if (m != j) value *= (s - T::c[m]) / (T::c[j] - T::c[m]);
    return value;
  }

  std::array<StateVector<N>, S> z_, k_, guess_;
  StateVector<N> stage_, increment_, lastX_;
  double extrapolate_[S][S];
  bool haveLast_ = false;
  double lastEnd_ = 0.0, lastH_ = 0.0;
  const OdeSystem<N>* lastSystem_ = nullptr;
  long long evaluations_ = 0, iterations_ = 0, capped_ = 0;
};

template <int N>
using GaussLegendre2 = GaussLegendre<N, 2>;
template <int N>
using GaussLegendre3 = GaussLegendre<N, 3>;

}  // namespace hemiroll::physics
