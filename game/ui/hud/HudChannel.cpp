#include "game/ui/hud/HudChannel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "engine/physics/Energy.h"
#include "engine/physics/Orientation.h"
#include "engine/physics/StateKinematics.h"

namespace hemiroll::game {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

// In TaskVariable order, then omega_norm. Positions in millimetres (the
// targets are centimetres away, the bands a millimetre wide), angles in
// degrees (a player's intuition for tilt), rates per second of those.
constexpr std::array<PlayerUnit, task::kTaskVariableCount> kTaskUnits = {{
    {"mass point x", "mm", 1e3},
    {"mass point y", "mm", 1e3},
    {"mass point speed x", "mm/s", 1e3},
    {"mass point speed y", "mm/s", 1e3},
    {"spin x", "°/s", kDegrees},
    {"spin y", "°/s", kDegrees},
    {"spin z", "°/s", kDegrees},
    {"contact x", "mm", 1e3},
    {"contact y", "mm", 1e3},
    {"tilt u", "°", kDegrees},
    {"tilt v", "°", kDegrees},
    {"heading", "°", kDegrees},
    {"spin", "°/s", kDegrees},
}};

}  // namespace

PlayerUnit playerUnitOf(task::TaskVariable variable) { return kTaskUnits[static_cast<std::size_t>(variable)]; }

std::optional<HudChannel> HudChannel::fromName(std::string_view name) {
  if (const std::optional<task::TaskVariable> v = task::taskVariableFromName(name)) {
    if (*v == task::TaskVariable::omega_norm) return HudChannel(Source::OmegaNorm, 0, playerUnitOf(*v));
    return HudChannel(Source::StateSlot, static_cast<int>(*v), playerUnitOf(*v));
  }
  // The channels that are not state variables: LevelLoader's names.
  struct Named {
    std::string_view name;
    Source source;
    int index;
    PlayerUnit unit;
  };
  static constexpr std::array<Named, 8> kOthers = {{
      {"energy", Source::Energy, 0, {"energy", "mJ", 1e3}},
      {"proxy_x", Source::Proxy, 0, {"proxy x", "mm", 1e3}},
      {"proxy_y", Source::Proxy, 1, {"proxy y", "mm", 1e3}},
      {"proxy_z", Source::Proxy, 2, {"proxy z", "mm", 1e3}},
      {"force_x", Source::Force, 0, {"hand force x", "N", 1.0}},
      {"force_y", Source::Force, 1, {"hand force y", "N", 1.0}},
      {"force_z", Source::Force, 2, {"hand force z", "N", 1.0}},
      {"force_norm", Source::ForceNorm, 0, {"hand force", "N", 1.0}},
  }};
  for (const Named& n : kOthers)
    if (n.name == name) return HudChannel(n.source, n.index, n.unit);
  return std::nullopt;
}

double HudChannel::value(const haptics::ServoSnapshot& s, const physics::RollingDynamics& dynamics) const {
  const std::size_t i = static_cast<std::size_t>(index_);
  switch (source_) {
    case Source::StateSlot: return s.state[i];  // TaskVariable order is the 12-state's slot order
    case Source::OmegaNorm:
      return std::hypot(s.state[physics::force_slot::w_x], s.state[physics::force_slot::w_y],
                        s.state[physics::force_slot::w_z]);
    case Source::Energy: return physics::mechanicalEnergy(dynamics, physics::forceStateOf(s.state)).total();
    case Source::Proxy: return s.proxyPosition[i];
    case Source::Force: return s.handForce[i];
    case Source::ForceNorm: return std::hypot(s.handForce[0], s.handForce[1], s.handForce[2]);
  }
  return 0.0;
}

Tilt tiltOf(const haptics::ServoSnapshot& s) {
  namespace slot = physics::force_slot;
  const physics::Orientation o = physics::makeOrientation(s.state[slot::u_o], s.state[slot::v_o], s.state[slot::psi]);
  const physics::Vec3 n = o.faceNormal();
  Tilt t;
  t.angle = std::acos(std::clamp(n.z(), -1.0, 1.0));
  const double h = std::hypot(n.x(), n.y());
  if (h > 0.0) {
    t.downhillX = n.x() / h;
    t.downhillY = n.y() / h;
  }
  return t;
}

}  // namespace hemiroll::game
