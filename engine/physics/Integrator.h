#pragma once
// One-step integrators behind one interface, so that the stepper, the servo
// loop and the tools select them by name. Fixed-size state, no allocation.

#include <string_view>

#include "engine/physics/OdeSystem.h"

namespace hemiroll::physics {

template <int N>
class AdaptiveIntegrator;

template <int N>
class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string_view name() const = 0;
  virtual int order() const = 0;
  // Advances x from t to t + h. h may be any positive value: the stepper
  // shortens steps to locate events.
  virtual void step(const OdeSystem<N>& system, double t, StateVector<N>& x, double h) = 0;
  // The step-size-controlled interface (AdaptiveIntegrator.h), or nullptr for
  // a fixed-step method. Lets the stepper and the registry tell them apart
  // without RTTI.
  virtual AdaptiveIntegrator<N>* adaptive() { return nullptr; }
  // True when step() is a pure function of (system, t, x, h): no history
  // (no starting guesses kept from earlier steps). The stepper may then skip
  // a step whose result it already knows (sleeping at an exact fixed point).
  virtual bool memoryless() const { return false; }
};

// The classical fourth-order Runge-Kutta method, the paper's choice (h = 1 ms).
template <int N>
class RungeKutta4 final : public Integrator<N> {
 public:
  std::string_view name() const override { return "rk4"; }
  int order() const override { return 4; }
  bool memoryless() const override { return true; }  // k1..k4 are scratch, overwritten every step

  void step(const OdeSystem<N>& f, double t, StateVector<N>& x, double h) override {
    const double half = 0.5 * h;
    f.derivative(t, x, k1_);
    stage_ = x + half * k1_;
    f.derivative(t + half, stage_, k2_);
    stage_ = x + half * k2_;
    f.derivative(t + half, stage_, k3_);
    stage_ = x + h * k3_;
    f.derivative(t + h, stage_, k4_);
    x += (h / 6.0) * (k1_ + 2.0 * (k2_ + k3_) + k4_);
  }

 private:
  StateVector<N> k1_, k2_, k3_, k4_, stage_;
};

}  // namespace hemiroll::physics
