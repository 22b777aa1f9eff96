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
};

}  // namespace hemiroll::physics
