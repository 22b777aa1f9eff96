#pragma once
// Advances a model with an integrator, step by step, and stops exactly at the
// edge of the domain (tip-over, off-face, non-finite). After an event the
// state is the last valid one, at the located event time, and stays finite.
//
// Fixed-step integrators: advance(h) takes one step of h; an event inside it
// is located by bisection on the length of a repeated step.
// Adaptive integrators (AdaptiveIntegrator.h): advance(h) and advanceTo(t)
// move the output time; the integrator takes its own steps, which may end
// beyond the output time, and the state at the output time comes from the
// dense output. Each accepted step's end is checked against the domain, and
// an event inside a step is located by bisection on the dense output (no
// re-integration), to kEventTimeTolerance in time; the interpolant's own error
// is of the order of the tolerance, so the event time is as accurate as the
// trajectory. An event is checked at step ends only: a crossing out and back
// within one step goes unseen (as with fixed steps).
//
// Sleeping (fixed-step, memoryless integrators on an autonomous system only):
// when a step returns its starting state bit for bit, the state is a fixed
// point of the step map x -> step(x, h). Because such a step depends on
// (x, h) alone, every later step of the same h gives the same state again, so
// the stepper stops calling the integrator and only advances the clock. It
// wakes (takes real steps again) when h changes, the system's input changes
// (inputRevision), the system stops being autonomous, or reset() is given a
// different state. A slept run is therefore bit-identical to one that keeps
// stepping. Typical case: a scene at rest (all rates exactly zero) with a
// held proxy that does not move.

#include <cmath>
#include <cstring>
#include <limits>

#include "engine/physics/AdaptiveIntegrator.h"

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
      : system_(system), integrator_(integrator), adaptive_(integrator.adaptive()) {
    reset(x0, t0);
  }

  // For an adaptive integrator this restarts it (step size and history).
  // A sleeping stepper stays asleep when given its own state back (the sim's
  // loop resets the clock onto the grid every step).
  void reset(const StateVector<N>& x0, double t0) {
    if (sleeping_ && !sameBits(x0, x_)) sleeping_ = false;
    x_ = x0;
    t_ = t0;
    event_ = classify(t0, x0);
    started_ = false;
    pending_ = DomainEvent::None;
  }

  StepReport advance(double h) {
    if (event_ != DomainEvent::None) return {event_, t_};
    if (adaptive_ != nullptr) return advanceAdaptive(t_ + h);
    if (sleeping_) {
      if (stillAsleep(h)) {
        t_ += h;  // the step would return x_ unchanged, and classify(x_) is None
        ++sleptSteps_;
        return {DomainEvent::None, t_};
      }
      sleeping_ = false;
    }
    StateVector<N> next = x_;
    integrator_.step(system_, t_, next, h);
    const DomainEvent e = classify(t_ + h, next);
    if (e == DomainEvent::None) {
      if (sameBits(next, x_) && canSleep()) fallAsleep(h);
      x_ = next;
      t_ += h;
      return {DomainEvent::None, t_};
    }
    locateEvent(h, e);
    return {event_, t_};
  }

  // To the output time tEnd (> time()). For a fixed-step integrator this is
  // one step of tEnd - time() with the clock then set to tEnd exactly; for an
  // adaptive one, the integrator's own steps and the dense output at tEnd.
  StepReport advanceTo(double tEnd) {
    if (event_ != DomainEvent::None) return {event_, t_};
    if (adaptive_ != nullptr) return advanceAdaptive(tEnd);
    const StepReport report = advance(tEnd - t_);
    if (report.event == DomainEvent::None) t_ = tEnd;
    return {event_, t_};
  }

  bool adaptive() const { return adaptive_ != nullptr; }
  const StateVector<N>& state() const { return x_; }
  double time() const { return t_; }
  DomainEvent event() const { return event_; }
  bool halted() const { return event_ != DomainEvent::None; }
  bool sleeping() const { return sleeping_; }
  // Steps skipped while asleep, since construction.
  long long sleptSteps() const { return sleptSteps_; }

 private:
  static bool sameBits(const StateVector<N>& a, const StateVector<N>& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * N) == 0;
  }
  bool canSleep() const { return integrator_.memoryless() && system_.autonomous(); }
  void fallAsleep(double h) {
    sleeping_ = true;
    sleepStep_ = h;
    sleepRevision_ = system_.inputRevision();
  }
  // Bitwise on h: any other step length could round differently.
  bool stillAsleep(double h) const {
    return std::memcmp(&h, &sleepStep_, sizeof h) == 0 && system_.inputRevision() == sleepRevision_ &&
           system_.autonomous();
  }

  DomainEvent classify(double t, const StateVector<N>& x) const { return system_.domainEvent(t, x); }

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

  StepReport advanceAdaptive(double tEnd) {
    AdaptiveIntegrator<N>& a = *adaptive_;
    if (!started_) {
      a.start(system_, t_, x_);
      started_ = true;
    }
    // An event located in an earlier step, beyond that call's output time.
    if (pending_ != DomainEvent::None && pendingTime_ <= tEnd) {
      x_ = pendingState_;
      t_ = pendingTime_;
      event_ = pending_;
      return {event_, t_};
    }
    while (pending_ == DomainEvent::None && a.time() < tEnd) {
      // Steps are not limited by tEnd (dense output serves it), but by the
      // horizon that float times allow.
      if (!a.takeStep(system_, std::numeric_limits<double>::max())) {
        // Step-size underflow: a singularity of the model or its coordinates
        // (1 / cos v_o at the rim). Stop at the last good state.
        x_ = a.state();
        t_ = a.time();
        event_ = DomainEvent::NonFinite;
        return {event_, t_};
      }
      const DomainEvent e = classify(a.time(), a.state());
      if (e != DomainEvent::None) locateOnDenseOutput(e);
    }
    if (pending_ != DomainEvent::None && pendingTime_ <= tEnd) {
      x_ = pendingState_;
      t_ = pendingTime_;
      event_ = pending_;
      return {event_, t_};
    }
    if (a.time() == tEnd) {
      x_ = a.state();
    } else {
      a.interpolate(tEnd, x_);
    }
    t_ = tEnd;
    return {DomainEvent::None, t_};
  }

  // Bisection in time on the last accepted step's dense output: the latest
  // time found inside, to kEventTimeTolerance.
  void locateOnDenseOutput(DomainEvent eventAtEnd) {
    AdaptiveIntegrator<N>& a = *adaptive_;
    double inside = a.stepBegin(), outside = a.time();
    StateVector<N> best, probe;
    a.interpolate(inside, best);
    DomainEvent event = eventAtEnd;
    while (outside - inside > kEventTimeTolerance) {
      const double mid = 0.5 * (inside + outside);
      if (mid <= inside || mid >= outside) break;  // no double in between
      a.interpolate(mid, probe);
      const DomainEvent e = classify(mid, probe);
      if (e == DomainEvent::None) {
        inside = mid;
        best = probe;
      } else {
        outside = mid;
        event = e;
      }
    }
    pending_ = event;
    pendingTime_ = inside;
    pendingState_ = best;
  }

  const OdeSystem<N>& system_;
  Integrator<N>& integrator_;
  AdaptiveIntegrator<N>* adaptive_;
  StateVector<N> x_;
  double t_ = 0.0;
  DomainEvent event_ = DomainEvent::None;
  bool started_ = false;
  // Fixed-step sleeping at an exact fixed point of the step map.
  bool sleeping_ = false;
  double sleepStep_ = 0.0;
  unsigned long long sleepRevision_ = 0;
  long long sleptSteps_ = 0;
  // Adaptive only: an event found in a step that ends past the output time.
  DomainEvent pending_ = DomainEvent::None;
  double pendingTime_ = 0.0;
  StateVector<N> pendingState_;
};

}  // namespace hemiroll::physics
