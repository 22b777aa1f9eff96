#include "engine/autopilot/SpinBrake.h"

#include <cmath>

#include "engine/autopilot/PlantModel.h"
#include "engine/autopilot/UprightContact.h"

namespace hemiroll::autopilot {

using physics::Vec3;

namespace {

// One brake of `amplitude` anticlockwise from rest upright with no spin:
// the spin the rest keeps afterwards, or false if the model left its
// domain or the helix tilted past `largestTilt`.
bool rollBrake(const physics::HemisphereParams& params, const physics::CouplingDef& coupling, const HelixParams& helix,
               const SettleGain& gain, double dt, const SpinBrakeDef& def, double amplitude, double& change) {
  PlantModel plant(params, coupling, dt);
  plant.reset(physics::ForceDrivenState::Zero(), 0.0);
  const physics::ModelConstants& constants = plant.constants();
  HelixPolicy law(constants, helix, dt);
  law.setSettleGain(gain);
  law.setGoal(Goal{});  // no target: it settles where it stops
  Vec3 last(0.0, 0.0, params.radius);
  law.startAt(last);
  law.brake(amplitude, std::abs(def.rate), def.lock);
  const long long ticks = std::llround((def.lock + def.settle) / dt);
  for (long long k = 0; k < ticks; ++k) {
    const Vec3 proxy = law.proxyFor(plant.state());
    if (plant.tick(proxy, (proxy - last) / dt) != physics::DomainEvent::None) return false;
    last = proxy;
    if (uprightContact(constants, plant.state()).tilt > def.largestTilt) return false;
  }
  change = plant.state()[physics::force_slot::w_z];
  return true;
}

}  // namespace

SpinBrakeTable spinBrakeTableFor(const physics::HemisphereParams& params, const physics::CouplingDef& coupling,
                                 const HelixParams& helix, const SettleGain& gain, double dt,
                                 const SpinBrakeDef& def) {
  SpinBrakeTable table;
  table.rate = std::abs(def.rate);
  table.lock = def.lock;
  for (const double a : def.amplitudes) {
    double change = 0.0;
    if (!rollBrake(params, coupling, helix, gain, dt, def, a, change)) break;
    // Only where a bigger circle takes out more: the choice interpolates.
    if (change <= (table.rows > 0 ? table.change[static_cast<std::size_t>(table.rows - 1)] : 0.0)) break;
    table.amplitude[static_cast<std::size_t>(table.rows)] = a;
    table.change[static_cast<std::size_t>(table.rows)] = change;
    ++table.rows;
  }
  return table;
}

SpinBrakeCommand spinBrakeFor(const SpinBrakeTable& table, double spin) {
  SpinBrakeCommand c;
  if (table.rows == 0 || spin == 0.0) return c;
  const double want = std::abs(spin);
  double a0 = 0.0, j0 = 0.0;
  c.amplitude = table.amplitude[static_cast<std::size_t>(table.rows - 1)];
  c.change = table.change[static_cast<std::size_t>(table.rows - 1)];
  for (int i = 0; i < table.rows; ++i) {
    const double a1 = table.amplitude[static_cast<std::size_t>(i)], j1 = table.change[static_cast<std::size_t>(i)];
    if (want <= j1) {
      c.amplitude = a0 + (a1 - a0) * (want - j0) / (j1 - j0);
      c.change = want;
      break;
    }
    a0 = a1;
    j0 = j1;
  }
  c.valid = true;
  c.rate = spin > 0.0 ? -table.rate : table.rate;  // a stop leaves J changed in the circle's own sense
  c.lock = table.lock;
  return c;
}

void startBrake(HelixPolicy& law, const SpinBrakeCommand& command) {
  if (command.valid) law.brake(command.amplitude, command.rate, command.lock);
}

}  // namespace hemiroll::autopilot
