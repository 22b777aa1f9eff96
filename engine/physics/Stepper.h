#pragma once
// Advances a model with an integrator, step by step, and stops exactly at the
// edge of the domain (tip-over, off-face, non-finite). After an event the
// state is the last valid one, at the located event time, and stays finite.

#include <cmath>

#include "engine/physics/Integrator.h"

namespace hemiroll::physics {

struct StepReport {
  DomainEvent event = DomainEvent::None;
  double time = 0.0;  // time of the state after the step (the event time if one fired) [s]
};

template <int N>
class Stepper {
 public:
  // Events are located by bisection on the step length to this precision [s].
  static constexpr double kEventTimeTolerance = 1e-10;

  Stepper(const OdeSystem<N>& system, Integrator<N>& integrator, const StateVector<N>& x0, double t0 = 0.0)
      : system_(system), integrator_(integrator) {
    reset(x0, t0);
  }

  void reset(const StateVector<N>& x0, double t0) {
    x_ = x0;
    t_ = t0;
    event_ = classify(t0, x0);
  }

  StepReport advance(double h) {
    if (event_ != DomainEvent::None) return {event_, t_};
    StateVector<N> next = x_;
    integrator_.step(system_, t_, next, h);
    const DomainEvent e = classify(t_ + h, next);
    if (e == DomainEvent::None) {
      x_ = next;
      t_ += h;
      return {DomainEvent::None, t_};
    }
    locateEvent(h, e);
    return {event_, t_};
  }

  const StateVector<N>& state() const { return x_; }
  double time() const { return t_; }
  DomainEvent event() const { return event_; }
  bool halted() const { return event_ != DomainEvent::None; }

 private:
  DomainEvent classify(double t, const StateVector<N>& x) const {
    const bool finite = x.allFinite();
    return classifyDomain(finite ? system_.margins(t, x) : DomainMargins{0.0, 0.0}, finite);
  }

  // Bisection on the step length: the largest h' that stays inside. Each probe
  // restarts from the accepted state, so the result is what an integration
  // with a shorter last step would give.
  void locateEvent(double h, DomainEvent eventAtEnd) {
    double inside = 0.0, outside = h;
    StateVector<N> best = x_;
    DomainEvent event = eventAtEnd;
    while (outside - inside > kEventTimeTolerance) {
      const double mid = 0.5 * (inside + outside);
      StateVector<N> probe = x_;
      integrator_.step(system_, t_, probe, mid);
      const DomainEvent e = classify(t_ + mid, probe);
      if (e == DomainEvent::None) {
        inside = mid;
        best = probe;
      } else {
        outside = mid;
        event = e;
      }
    }
    x_ = best;
    t_ += inside;
    event_ = event;
  }

  const OdeSystem<N>& system_;
  Integrator<N>& integrator_;
  StateVector<N> x_;
  double t_ = 0.0;
  DomainEvent event_ = DomainEvent::None;
};

}  // namespace hemiroll::physics
