#include "game/hud/HudChannel.h"

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
constexpr std::array<PlayerUnit, script::kTaskVariableCount> kTaskUnits = {{
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

PlayerUnit playerUnitOf(script::TaskVariable variable) { return kTaskUnits[static_cast<std::size_t>(variable)]; }

std::optional<HudChannel> HudChannel::fromName(std::string_view name) {
  if (const std::optional<script::TaskVariable> v = script::taskVariableFromName(name)) {
    if (*v == script::TaskVariable::omega_norm) return HudChannel(Source::OmegaNorm, 0, playerUnitOf(*v));
    return HudChannel(Source::StateSlot, static_cast<int>(*v), playerUnitOf(*v));
  }
  if (name == "energy") return HudChannel(Source::Energy, 0, {"energy", "mJ", 1e3});
  if (name == "force_norm") return HudChannel(Source::ForceNorm, 0, {"hand force", "N", 1.0});
  static constexpr std::array<const char*, 3> kAxes = {"x", "y", "z"};
  static constexpr std::array<const char*, 3> kProxy = {"proxy x", "proxy y", "proxy z"};
  static constexpr std::array<const char*, 3> kForce = {"hand force x", "hand force y", "hand force z"};
  for (int i = 0; i < 3; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    if (name.size() == 7 && name.substr(0, 6) == "proxy_" && name.substr(6) == kAxes[k])
      return HudChannel(Source::Proxy, i, {kProxy[k], "mm", 1e3});
    if (name.size() == 7 && name.substr(0, 6) == "force_" && name.substr(6) == kAxes[k])
      return HudChannel(Source::Force, i, {kForce[k], "N", 1.0});
  }
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
