#pragma once
// What the screen shows a player, as plain numbers: all a simulated person
// may base a decision on. The game fills it each tick from what it draws
// (the floor with the contact point, the target and its band; the
// hemisphere, whose lean the tilt gauge repeats; the mass point on the face
// dial; the player's own proxy; the HUD's spin), and, when the game's aids
// are on, the hint and the force cue. The person sees it late
// (HumanDef::visualDelay).
//
// Frames: scene, x and y on the floor, z up [m].

#include "engine/physics/StateLayout.h"

namespace hemiroll::human {

// The hint at a person's bandwidth (game/trial/HintCoach): what to do over
// the next second or two, never a point a fraction of a second ahead.
enum class HintKind {
  None,
  Stir,    // trace the ring: centre, radius, pace (rate, with its sense)
  Settle,  // bring the proxy over `point` and keep it still there
};

struct HintCue {
  HintKind kind = HintKind::None;
  physics::Vec2 centre = physics::Vec2::Zero();  // Stir: the ring's centre on the floor [m]
  double radius = 0.0;                           // Stir [m]
  double rate = 0.0;                             // Stir: [rad/s], positive anticlockwise seen from above
  physics::Vec2 point = physics::Vec2::Zero();   // Settle: where the proxy should stand [m]
};

struct ScreenView {
  double time = 0.0;                                   // [s]
  physics::Vec2 contact = physics::Vec2::Zero();       // the contact point on the floor [m]
  physics::Vec3 normal = physics::Vec3::UnitZ();       // the face's normal (the tilt gauge) [-]
  physics::Vec3 mass = physics::Vec3::Zero();          // the mass point [m]
  physics::Vec3 proxy = physics::Vec3::Zero();         // the player's proxy [m]
  double spin = 0.0;                                   // turning about the vertical, as the HUD shows it [rad/s]
  bool engaged = false;                                // the coupling holds the mass point
  // The task's contact target (the ring on the floor) and its band.
  bool contactTargetSet = false;
  physics::Vec2 contactTarget = physics::Vec2::Zero();  // [m]
  double contactTolerance = 0.0;                        // [m]
  // The task also judges the mass point or the lean (bands on p or u_co):
  // the hemisphere must end upright, not merely leaning onto the target.
  bool uprightRequired = false;
  // A lean the task asks for (a band on u_co): the face's normal at that
  // lean, and the band's half-width [rad].
  bool leanTargetSet = false;
  physics::Vec3 leanTarget = physics::Vec3::UnitZ();
  double leanTolerance = 0.0;
  // A heading the task asks for (a band on psi): the HUD says how far to
  // turn it and which way ("heading: turn it 8.6 degrees clockwise").
  bool headingSet = false;
  double headingError = 0.0;      // target - heading, wrapped, positive anticlockwise seen from above [rad]
  double headingTolerance = 0.0;  // [rad]
  // The band the task puts on the spin, as the HUD gives it ("spinning at
  // 1.2 degrees/s: let it settle (±0.57)"); 0 without one [rad/s].
  double spinTolerance = 0.0;
  int stage = 0;
  // The game's aids.
  HintCue hint;
  bool forceCueShown = false;
  physics::Vec3 forceCue = physics::Vec3::Zero();  // the coupling force on the mass point, drawn [N]
};

}  // namespace hemiroll::human
