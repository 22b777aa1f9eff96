#pragma once
// A small non-autonomous, nonlinear problem with a closed-form solution, for
// measuring orders of convergence without a numerical reference:
//   x0' = cos(t) x0        -> x0 = exp(sin t)        (x0(0) = 1)
//   x1' = -2 t x1^2        -> x1 = 1 / (1 + t^2)     (x1(0) = 1)
// The explicit time dependence checks that stages see the right t + c_i h.

#include <cmath>

#include "engine/physics/AdaptiveIntegrator.h"
#include "engine/physics/OdeSystem.h"

namespace hemiroll::test {

struct KnownSolutionSystem final : physics::OdeSystem<2> {
  void derivative(double t, const physics::StateVector<2>& x, physics::StateVector<2>& dxdt) const override {
    dxdt[0] = std::cos(t) * x[0];
    dxdt[1] = -2.0 * t * x[1] * x[1];
  }
  physics::DomainMargins margins(double, const physics::StateVector<2>&) const override { return {1.0, 1.0}; }
  static physics::StateVector<2> exact(double t) { return {std::exp(std::sin(t)), 1.0 / (1.0 + t * t)}; }
};

// One adaptive run of method M over the known solution, from 0 to T at
// tolerance tol: how far it got, its error there (max norm) and its work.
struct KnownSolutionRun {
  bool reached = false;
  double t = 0.0, error = 0.0;
  long long evaluations = 0;
};

template <class M>
KnownSolutionRun runKnownSolution(double tol, double T = 3.0) {
  const KnownSolutionSystem f;
  M m;
  m.setTolerance(tol);
  KnownSolutionRun run;
  physics::StateVector<2> x = KnownSolutionSystem::exact(0.0);
  run.reached = m.advanceTo(f, run.t, x, T);
  run.error = (x - KnownSolutionSystem::exact(T)).cwiseAbs().maxCoeff();
  run.evaluations = m.statistics().evaluations;
  return run;
}

}  // namespace hemiroll::test
