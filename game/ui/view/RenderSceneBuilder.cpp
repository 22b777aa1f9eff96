#include "game/ui/view/RenderSceneBuilder.h"

#include <cmath>

#include "engine/physics/Orientation.h"
#include "engine/physics/StateKinematics.h"

namespace hemiroll::game {

namespace {

using task::TaskVariable;
namespace slot = physics::force_slot;

// Wider than any floor: the renderer clips a free component's band to its floor.
constexpr double kFreeBand = 1e3;

void fillTargets(const task::LevelDef& level, const physics::ForceDrivenState& x, std::size_t stage,
                 render::RenderScene& scene) {
  scene.targets.clear();
  if (stage >= level.task.stages.size()) return;
  render::TargetMarker marker;
  marker.halfWidth = {kFreeBand, kFreeBand};
  bool any = false, inside = true;
  for (const task::TargetDef& t : level.task.stages[stage].targets) {
    int axis = -1;
    if (t.variable == TaskVariable::u_a) axis = 0;
    if (t.variable == TaskVariable::v_a) axis = 1;
    if (axis < 0) continue;
    any = true;
    marker.position[axis] = t.value;
    marker.halfWidth[axis] = t.tolerance;
    const double value = x[axis == 0 ? slot::u_a : slot::v_a];
    inside = inside && std::abs(value - t.value) <= t.tolerance;
  }
  if (!any) return;
  marker.inside = inside;
  scene.targets.push_back(marker);
}

void fillZones(const task::LevelDef& level, render::RenderScene& scene) {
  scene.forbidden.clear();
  for (const task::ZoneDef& z : level.task.forbidden) {
    render::ZoneMarker m;
    m.circle = z.shape == task::ZoneShape::Circle;
    m.centre = z.center;
    m.radius = z.radius;
    m.min = z.min;
    m.max = z.max;
    scene.forbidden.push_back(m);
  }
}

}  // namespace

void fillFromState(const task::LevelDef& level, const physics::ForceDrivenState& x, std::size_t stage,
                   render::RenderScene& scene) {
  const double radius = level.params.radius;
  const physics::Orientation o = physics::makeOrientation(x[slot::u_o], x[slot::v_o], x[slot::psi]);
  scene.radius = radius;
  scene.centre = {x[slot::u_a], x[slot::v_a], radius};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) scene.orientation[3 * i + j] = o.R(i, j);
  scene.massPoint = {x[slot::x_p], x[slot::y_p]};
  fillTargets(level, x, stage, scene);
  fillZones(level, scene);
  // assign keeps the capacity: no allocation after the first frame.
  scene.examplePath.assign(level.scene.examplePath.begin(), level.scene.examplePath.end());
}

std::vector<render::PropDef> propsOf(const task::LevelDef& level) {
  std::vector<render::PropDef> props;
  for (const task::PropDef& p : level.scene.props)
    props.push_back({p.mesh, p.position, p.size, p.yaw,
                     {float(p.colour[0]), float(p.colour[1]), float(p.colour[2]), 1.0f}});
  return props;
}

void fillGhost(const task::LevelDef& level, const haptics::ServoSnapshot& ghost, render::GhostPose& out) {
  const physics::ForceDrivenState x = physics::forceStateOf(ghost.state);
  const physics::Orientation o = physics::makeOrientation(x[slot::u_o], x[slot::v_o], x[slot::psi]);
  out.shown = true;
  out.centre = {x[slot::u_a], x[slot::v_a], level.params.radius};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.orientation[3 * i + j] = o.R(i, j);
  out.massPoint = {x[slot::x_p], x[slot::y_p]};
}

void fillFromSnapshot(const task::LevelDef& level, const haptics::ServoSnapshot& snapshot, std::size_t stage,
                      render::RenderScene& scene) {
  const physics::ForceDrivenState x = physics::forceStateOf(snapshot.state);
  fillFromState(level, x, stage, scene);
  scene.showProxy = true;
  scene.proxyPosition = snapshot.proxyPosition;
  scene.springOn = snapshot.engagement != haptics::Engagement::Disengaged;
  scene.force = snapshot.handForce;
  scene.time = snapshot.time;
}

}  // namespace hemiroll::game
