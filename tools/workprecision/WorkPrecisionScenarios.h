#pragma once
// The scenes of the work-precision study (issue 3): each is a model, a start
// state and a horizon, small enough to run a few hundred times.
//   free      free motion (12-state), gently tilted and spinning, 0.35 s (left_face at 0.3557 s)
//   tether    undamped M2 spring to a fixed proxy (12-state), 4 s
//   m3moving  M3 coupling (paper gains, alpha 2) to a circling proxy, 10 s
//   rose      the paper's rose drive (8-state), paper masses, 6 s
//   roseheavy the rose drive with m_s = 1 kg, 15 s (35 s is past the window)
// Horizons lie inside the predictability window; the program checks that
// with two references at different tolerances.

#include <memory>
#include <string>
#include <vector>

#include "engine/physics/ForceDrivenSystem.h"
#include "engine/physics/RoseDrive.h"

namespace hemiroll::tools {

template <int N>
struct Scenario {
  std::string name;
  std::string description;
  const physics::OdeSystem<N>* system = nullptr;
  physics::StateVector<N> x0;
  double horizon = 0.0;  // [s]
};

// Owns the systems and the inputs they point to.
class ScenarioSet {
 public:
  // quick: horizons of 1 s (for the ctest smoke run).
  explicit ScenarioSet(bool quick);

  const std::vector<Scenario<12>>& forceDriven() const { return force_; }
  const std::vector<Scenario<8>>& prescribed() const { return rose_; }

 private:
  std::vector<std::unique_ptr<physics::ForceDrivenSystem>> forceSystems_;
  std::vector<std::unique_ptr<physics::ProxyTrajectory>> proxies_;
  std::vector<std::unique_ptr<physics::RoseDrive>> roses_;
  std::vector<std::unique_ptr<physics::PrescribedDriveSystem>> roseSystems_;
  std::vector<Scenario<12>> force_;
  std::vector<Scenario<8>> rose_;
};

// The undamped M2 tether of the invariant study: system, start, proxy position.
struct Tether {
  std::unique_ptr<physics::ForceDrivenSystem> system;
  physics::ForceDrivenState x0;
  physics::Vec3 proxy;
  // E + (1/2) k_r |r_p - r_h|^2, conserved exactly (physics-notes.md).
  double invariant(const physics::ForceDrivenState& x) const;
};
Tether makeTether();

}  // namespace hemiroll::tools
