#include "tools/bench/NaiveRk4Anchor.h"

#include <array>

#include "engine/physics/Physics.h"

namespace hemiroll::bench {

namespace {

using State = std::array<double, 12>;

// The model's right-hand side on plain arrays: what a first implementation
// calls, through the model's public interface.
void rates(const physics::ForceDrivenSystem& system, const State& x, State& dxdt) {
  physics::ForceDrivenState in, out;
  for (int i = 0; i < 12; ++i) in[i] = x[i];
  system.derivative(0.0, in, out);
  for (int i = 0; i < 12; ++i) dxdt[i] = out[i];
}

}  // namespace

double naiveRk4Anchor(long long steps) {
  physics::ForceDrivenSystem system{physics::HemisphereParams{}};
  system.setFree();
  // Tilted, spinning, mass point off centre, psi beyond pi/4 (PhysicsBench's typical state).
  const State start{0.012, -0.006, 0.03, 0.02, 0.4, -0.3, 1.2, 0.01, -0.02, 0.25, -0.15, 2.3};
  State x = start, k1, k2, k3, k4, stage;
  const double h = 1e-3;
  double sum = 0.0;
  for (long long n = 0; n < steps; ++n) {
    rates(system, x, k1);
    for (int i = 0; i < 12; ++i) stage[i] = x[i] + 0.5 * h * k1[i];
    rates(system, stage, k2);
    for (int i = 0; i < 12; ++i) stage[i] = x[i] + 0.5 * h * k2[i];
    rates(system, stage, k3);
    for (int i = 0; i < 12; ++i) stage[i] = x[i] + h * k3[i];
    rates(system, stage, k4);
    for (int i = 0; i < 12; ++i) x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    // Back to the typical state every 0.1 s of motion, as PhysicsBench
    // stays on it (a free hemisphere far from it may tip over).
    if (n % 100 == 99) {
      sum += x[0];
      x = start;
    }
  }
  return sum + x[0];
}

}  // namespace hemiroll::bench
