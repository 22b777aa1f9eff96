#include "game/trial/ObservationBuilder.h"

#include <algorithm>

#include "engine/physics/ForceDrivenSystem.h"

namespace hemiroll::game {

namespace {

script::Triple3 triple(const physics::Real3& v) { return {v.x, v.y, v.z}; }
script::Triple3 triple(const physics::Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

void ObservationBuilder::fill(double time, const physics::ForceDrivenState& x, const haptics::ServoSnapshot& snapshot,
                              const task::TaskJudge& judge, script::BotObservation& out) const {
  fillKinematics(time, x, snapshot, out);
  fillTask(judge, out);
}

void ObservationBuilder::fillKinematics(double time, const physics::ForceDrivenState& x,
                                        const haptics::ServoSnapshot& snapshot, script::BotObservation& out) const {
  using namespace physics::force_slot;
  out.time = time;
  for (int i = 0; i < 12; ++i) out.state[static_cast<std::size_t>(i)] = x[i];

  const physics::RollingGeometry g = physics::geometryOf(constants_, x);
  const physics::Vec3 omega(x[w_x], x[w_y], x[w_z]);
  const double radius = constants_.params.radius;
  const physics::PointKinematics point = physics::pointKinematics(g, radius, x[u_a], x[v_a], omega);
  out.mass = triple(point.position);
  out.massVelocity = triple(point.velocity);
  out.centre = {x[u_a], x[v_a], radius};
  out.contact = {x[u_a], x[v_a], 0.0};
  out.faceX = triple(g.frame.toBase(g.frame.i));
  out.faceY = triple(g.frame.toBase(g.frame.j));
  out.normal = triple(g.frame.toBase(g.frame.k));

  out.proxy = snapshot.proxyPosition;
  out.force = snapshot.handForce;
  const haptics::Triple& f = snapshot.renderedForce;
  out.deviceForce = triple(mapping_.forceToScene(haptics::Vec3(f[0], f[1], f[2])));
  out.proxyDistance = snapshot.proxyDistance;
  out.engaged = snapshot.engagement == haptics::Engagement::Engaged;
  out.forceShare = snapshot.rampScale;
}

void ObservationBuilder::fillTask(const task::TaskJudge& judge, script::BotObservation& out) {
  judge.slotTargets(out.target, out.tolerance, out.targetSet);
  out.omegaNormSet = false;
  for (const task::ComponentStatus& c : judge.components()) {
    if (c.variable != task::TaskVariable::omega_norm) continue;
    out.omegaNormSet = true;
    out.omegaNormTarget = c.target;
    out.omegaNormTolerance = c.tolerance;
  }
  const auto& forbidden = judge.task().forbidden;
  out.zoneCount = static_cast<int>(std::min<std::size_t>(forbidden.size(), script::BotObservation::kMaxZones));
  for (int i = 0; i < out.zoneCount; ++i) {
    const task::ZoneDef& z = forbidden[static_cast<std::size_t>(i)];
    physics::PlaneZone& o = out.zones[static_cast<std::size_t>(i)];
    o.circle = z.shape == task::ZoneShape::Circle;
    o.centre = z.center;
    o.radius = z.radius;
    o.min = z.min;
    o.max = z.max;
  }
  out.timeLimit = judge.task().timeLimit;
  out.holdTime = judge.requiredHold();
  out.held = judge.holdTime();
  out.stage = judge.stage();
}

}  // namespace hemiroll::game
