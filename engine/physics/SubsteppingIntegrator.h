#pragma once
// A fixed-step integrator that splits every step into a fixed number of equal
// substeps (the stability policy of CouplingStability.h). With one substep it
// calls the wrapped method exactly as asked, so it changes nothing where it
// is not needed (bit for bit). The count is chosen once, from the coupling
// and the nominal step, so that the run is deterministic; shortened steps
// (event location, a last partial step) are split into the same count, which
// only makes them more stable.

#include "engine/physics/Integrator.h"

namespace hemiroll::physics {

template <int N>
class SubsteppingIntegrator final : public Integrator<N> {
 public:
  // Does not own `inner`. substeps >= 1.
  SubsteppingIntegrator(Integrator<N>& inner, int substeps) : inner_(inner), substeps_(substeps < 1 ? 1 : substeps) {}

  std::string_view name() const override { return inner_.name(); }
  int order() const override { return inner_.order(); }
  bool memoryless() const override { return inner_.memoryless(); }
  int substeps() const { return substeps_; }

  void step(const OdeSystem<N>& f, double t, StateVector<N>& x, double h) override {
    if (substeps_ == 1) {
      inner_.step(f, t, x, h);
      return;
    }
    const double sub = h / substeps_;
    // t + i * sub, not an accumulated sum, so that stage times do not drift.
    for (int i = 0; i < substeps_; ++i) inner_.step(f, t + i * sub, x, sub);
  }

 private:
  Integrator<N>& inner_;
  int substeps_;
};

}  // namespace hemiroll::physics
