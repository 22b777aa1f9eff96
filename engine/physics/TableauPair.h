#pragma once
// An explicit embedded Runge-Kutta pair read from its Butcher table: the
// stages row by row, the higher-order solution propagated, the error from
// the weights' difference b - b_hat, and the derivative at the end of an
// accepted step evaluated once (the next step's first stage and the dense
// output's end slope; ExplicitPair's cubic Hermite). The Verner pairs are
// this with their tables (Verner76.h, Verner98.h). The table's zeros are
// skipped, which changes no sum.
//
// Table: static constexpr kName, kOrder (of b), kStages, c[kStages],
// a[kStages][kStages] (row i: a_ij, j < i), b[kStages], bHat[kStages].

#include <array>
#include <string_view>

#include "engine/physics/ExplicitPair.h"

namespace hemiroll::physics {

template <int N, class Table>
class TableauPair final : public ExplicitPair<N> {
 public:
  std::string_view name() const override { return Table::kName; }
  int order() const override { return Table::kOrder; }
  void interpolate(double t, StateVector<N>& x) override { this->hermite(t, x); }

 protected:
  // The error estimate is of the embedded order, kOrder - 1: it is O(h^kOrder).
  int controlOrder() const override { return Table::kOrder; }

  double attempt(const OdeSystem<N>& f, double h) override {
    using T = Table;
    const double t = this->time();
    for (int i = 1; i < T::kStages; ++i) {
      StateVector<N> sum = T::a[i][0] * this->k1_;
      for (int j = 1; j < i; ++j)
        if (T::a[i][j] != 0.0) sum += T::a[i][j] * k_[j];
      this->stage_ = this->x_ + h * sum;
      f.derivative(t + T::c[i] * h, this->stage_, k_[i]);
    }
    this->countEvaluations(T::kStages - 1);
    StateVector<N> high = T::b[0] * this->k1_, error = (T::b[0] - T::bHat[0]) * this->k1_;
    for (int i = 1; i < T::kStages; ++i) {
      if (T::b[i] != 0.0) high += T::b[i] * k_[i];
      if (T::b[i] != T::bHat[i]) error += (T::b[i] - T::bHat[i]) * k_[i];
    }
    this->xNew_ = this->x_ + h * high;
    this->hTry_ = h;
    error *= h;
    const double err = std::sqrt(error.cwiseQuotient(this->errorWeights(this->x_, this->xNew_)).squaredNorm() / N);
    return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
  }

  void accept(const OdeSystem<N>& f) override {
    this->xPrev_ = this->x_;
    this->x_ = this->xNew_;
    this->k1Prev_ = this->k1_;
    this->hDone_ = this->hTry_;
    this->setTime(this->time() + this->hTry_);
    f.derivative(this->time(), this->x_, this->k1_);  // the next step's first stage and this one's end slope
    this->countEvaluations(1);
  }

 private:
  std::array<StateVector<N>, Table::kStages> k_;  // k_[0] unused: the first stage is k1_
};

}  // namespace hemiroll::physics
