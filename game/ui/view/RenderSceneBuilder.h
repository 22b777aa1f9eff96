#pragma once
// Level + model state -> engine/render's RenderScene: the game is the one
// place that knows both (engine/render knows no level, engine/script no
// renderer). Used by `hemiroll screenshot` and by the play screen, which
// calls fillFromSnapshot every frame with the servo loop's latest snapshot.
//
// Targets drawn: the contact point's (u_a, v_a) components of the given
// stage, as the band the judge tests (a free component: a band as wide as
// the floor). Forbidden zones: task.forbidden. Allocates nothing once the
// scene's vectors have grown to the level's counts.

#include "engine/haptics/ServoSnapshot.h"
#include "engine/physics/StateLayout.h"
#include "engine/render/RenderScene.h"
#include "engine/render/Renderer.h"
#include "engine/task/LevelDef.h"

namespace hemiroll::game {

// The pose (centre, R of eq. 6, radius, mass point), the stage's targets
// (with "inside" from the state) and the zones. Leaves the proxy, force,
// trace and camera as they are.
void fillFromState(const task::LevelDef& level, const physics::ForceDrivenState& state, std::size_t stage,
                   render::RenderScene& scene);

// The same from a servo snapshot, plus the proxy, the spring (drawn while
// the coupling is engaged or ramping) and F_h as the force arrow.
// The level's scenery for Renderer::setProps.
std::vector<render::PropDef> propsOf(const task::LevelDef& level);

// The ghost's pose from another run's snapshot (a replayed best).
void fillGhost(const task::LevelDef& level, const haptics::ServoSnapshot& ghost, render::GhostPose& out);

void fillFromSnapshot(const task::LevelDef& level, const haptics::ServoSnapshot& snapshot, std::size_t stage,
                      render::RenderScene& scene);

}  // namespace hemiroll::game
