#pragma once
// Observed order of convergence: the slope of log(error) against log(h) by
// least squares over a sequence of halvings.

#include <cmath>
#include <type_traits>
#include <vector>

namespace hemiroll::test {

inline double observedOrder(const std::vector<double>& steps, const std::vector<double>& errors) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double x = std::log(steps[i]), y = std::log(errors[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace hemiroll::test

#include "engine/physics/AdaptiveIntegrator.h"

namespace hemiroll::test {

// x(T) after n equal steps of method M from (0, x0): fixed-step methods
// through step(), adaptive ones through takeFixedStep() (the propagated
// solution of the pair, with no step-size control).
template <class M, int N>
physics::StateVector<N> integrateEqualSteps(const physics::OdeSystem<N>& f, const physics::StateVector<N>& x0,
                                            double T, int n) {
  M method;
  const double h = T / n;
  if constexpr (std::is_base_of_v<physics::AdaptiveIntegrator<N>, M>) {
    method.start(f, 0.0, x0);
    for (int i = 0; i < n; ++i) method.takeFixedStep(f, h);
    return method.state();
  } else {
    physics::StateVector<N> x = x0;
    for (int i = 0; i < n; ++i) method.step(f, i * h, x, h);
    return x;
  }
}

// Observed order over step counts n, 2n, 4n, ... against a reference x(T).
template <class M, int N>
double measuredOrder(const physics::OdeSystem<N>& f, const physics::StateVector<N>& x0, double T,
                     const physics::StateVector<N>& reference, int n0, int halvings, std::vector<double>* errorsOut = nullptr) {
  std::vector<double> steps, errors;
  for (int k = 0, n = n0; k <= halvings; ++k, n *= 2) {
    steps.push_back(T / n);
    errors.push_back((integrateEqualSteps<M, N>(f, x0, T, n) - reference).cwiseAbs().maxCoeff());
  }
  if (errorsOut) *errorsOut = errors;
  return observedOrder(steps, errors);
}

}  // namespace hemiroll::test
