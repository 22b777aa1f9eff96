#pragma once
// What an integrator sees of a model: x' = X(t, x), and where x stops being
// valid. Both the 12-state force-driven model and the 8-state prescribed drive
// implement it.

#include "engine/physics/DomainEvents.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::physics {

template <int N>
class OdeSystem {
 public:
  static constexpr int kDimension = N;
  virtual ~OdeSystem() = default;

  virtual void derivative(double t, const StateVector<N>& x, StateVector<N>& dxdt) const = 0;
  virtual DomainMargins margins(double t, const StateVector<N>& x) const = 0;
  // Which edge x has crossed (None while inside and finite), as classifyDomain
  // reads margins(). The stepper asks this after every step; a model may
  // answer faster where it can, but must give the same answer everywhere.
  virtual DomainEvent domainEvent(double t, const StateVector<N>& x) const {
    const bool finite = x.allFinite();
    return classifyDomain(finite ? margins(t, x) : DomainMargins{0.0, 0.0}, finite);
  }

  // True when derivative() and margins() ignore t with the current input (no
  // time-dependent drive): a step then depends on (x, h) only, which is what
  // lets the stepper sleep at an exact fixed point (Stepper.h).
  virtual bool autonomous() const { return false; }
  // Changes whenever the input changes (a new held proxy pose, face force or
  // mode); a sleeping stepper wakes when it does.
  virtual unsigned long long inputRevision() const { return 0; }
};

}  // namespace hemiroll::physics
