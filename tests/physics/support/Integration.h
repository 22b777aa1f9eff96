#pragma once
// Fixed-step integration helpers for the tests: a generic RK4 for the
// Newton-Euler model, and engine systems augmented with the work integral so
// that E(t) - E(0) and int F.v_p dt come out of the same RK4.

#include "engine/physics/Energy.h"
#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/Integrator.h"
#include "engine/physics/PrescribedDriveSystem.h"
#include "tests/physics/support/TestModel.h"

namespace hemiroll::test {

// Classical RK4 on any Eigen vector, with f(t, y) returning y'.
template <class Vector, class Derivative>
Vector integrateRk4(const Derivative& f, Vector y, double t0, double h, int steps) {
  double t = t0;
  for (int i = 0; i < steps; ++i) {
    const Vector k1 = f(t, y);
    const Vector k2 = f(t + 0.5 * h, (y + 0.5 * h * k1).eval());
    const Vector k3 = f(t + 0.5 * h, (y + 0.5 * h * k2).eval());
    const Vector k4 = f(t + h, (y + h * k3).eval());
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    t = t0 + (i + 1) * h;
  }
  return y;
}

// Engine systems through the engine's own RK4.
template <int N>
physics::StateVector<N> integrateEngine(const physics::OdeSystem<N>& system, physics::StateVector<N> x, double t0,
                                        double h, int steps) {
  physics::RungeKutta4<N> rk4;
  for (int i = 0; i < steps; ++i) rk4.step(system, t0 + i * h, x, h);
  return x;
}

// The 12-state model plus W' = F . v_p in slot 12.
class ForceDrivenWithWork final : public physics::OdeSystem<13> {
 public:
  explicit ForceDrivenWithWork(const physics::ForceDrivenSystem& system) : system_(system) {}
  void derivative(double t, const physics::StateVector<13>& x, physics::StateVector<13>& dxdt) const override;
  physics::DomainMargins margins(double t, const physics::StateVector<13>& x) const override {
    return system_.margins(t, x.head<12>());
  }

 private:
  const physics::ForceDrivenSystem& system_;
};

// The 8-state prescribed drive plus W' = (R N f) . v_p in slot 8.
class PrescribedWithWork final : public physics::OdeSystem<9> {
 public:
  explicit PrescribedWithWork(const physics::PrescribedDriveSystem& system) : system_(system) {}
  void derivative(double t, const physics::StateVector<9>& x, physics::StateVector<9>& dxdt) const override;
  physics::DomainMargins margins(double t, const physics::StateVector<9>& x) const override {
    return system_.margins(t, x.head<8>());
  }

 private:
  const physics::PrescribedDriveSystem& system_;
};

}  // namespace hemiroll::test
