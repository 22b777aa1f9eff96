#include "game/research/sweep/SweepGrid.h"

#include <stdexcept>

#include "engine/physics/StateLayout.h"
#include "game/research/sweep/StaticTilt.h"

namespace hemiroll::game {

SweepGrid::SweepGrid(task::SweepDef def) : def_(std::move(def)), size_(def_.pointCount()) {}

SweepPoint SweepGrid::point(long long index) const {
  if (index < 0 || index >= size_) throw std::out_of_range("sweep point index out of range");
  SweepPoint p;
  p.index = index;
  p.params = def_.params;
  p.rose = def_.rose;
  p.position.resize(def_.axes.size());
  long long rest = index;
  for (std::size_t a = def_.axes.size(); a-- > 0;) {
    const auto& values = def_.axes[a].values;
    const long long n = static_cast<long long>(values.size());
    p.position[a] = static_cast<int>(rest % n);
    rest /= n;
    task::setSweepParam(def_.axes[a].param, values[static_cast<std::size_t>(p.position[a])], p.params, p.rose);
  }
  if (def_.start == task::SweepStart::Equilibrium) p.startTilt = staticTilt(p.params, p.rose.r1 + p.rose.r2);
  return p;
}

task::ScenarioDef SweepGrid::scenario(const SweepPoint& point) const {
  task::ScenarioDef s;
  s.source = def_.source;
  s.params = point.params;
  s.drive.kind = task::DriveKind::Rose;
  s.drive.rose = point.rose;
  s.initial[physics::force_slot::u_o] = -point.startTilt;
  s.duration = def_.duration;
  s.timeStep = def_.timeStep;
  s.integrator = def_.integrator;
  s.tolerance = def_.tolerance;
  return s;
}

}  // namespace hemiroll::game
