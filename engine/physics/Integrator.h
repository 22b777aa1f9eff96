#pragma once
// One-step integrators behind one interface, so that the stepper, the servo
// loop and the tools select them by name. Fixed-size state, no allocation.

#include <string_view>

#include "engine/physics/OdeSystem.h"

// GCC's vectoriser would pair the elements of the stage loops (see
// RungeKutta4::step); other compilers vectorise at will and lose only speed.
#if defined(__GNUC__) && !defined(__clang__)
#define HEMIROLL_SCALAR_LOOPS [[gnu::optimize("no-tree-vectorize", "no-tree-slp-vectorize")]]
#else
#define HEMIROLL_SCALAR_LOOPS
#endif

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

  // Element by element, not in pairs: a right-hand side writes its rates one
  // double at a time, and a 16-byte load of two such fresh 8-byte stores
  // cannot be forwarded from the store buffer; it waits for both stores to
  // reach the cache, on every stage's path (docs/PERFORMANCE.md: 207 -> 184 ns
  // per 12-state step). The same operations in the same order: the same bits.
  HEMIROLL_SCALAR_LOOPS void step(const OdeSystem<N>& f, double t, StateVector<N>& x, double h) override {
    const double half = 0.5 * h;
    f.derivative(t, x, k1_);
    for (int i = 0; i < N; ++i) stage_[i] = x[i] + half * k1_[i];
    f.derivative(t + half, stage_, k2_);
    for (int i = 0; i < N; ++i) stage_[i] = x[i] + half * k2_[i];
    f.derivative(t + half, stage_, k3_);
    for (int i = 0; i < N; ++i) stage_[i] = x[i] + h * k3_[i];
    f.derivative(t + h, stage_, k4_);
    const double sixth = h / 6.0;
    for (int i = 0; i < N; ++i) x[i] += sixth * (k1_[i] + 2.0 * (k2_[i] + k3_[i]) + k4_[i]);
  }

 private:
  StateVector<N> k1_, k2_, k3_, k4_, stage_;
};

}  // namespace hemiroll::physics
