#pragma once
// What a person who has learned the technique in words (the paper's, Sec.
// 4.2, as the tutorials put it) does, deciding from one delayed view at a
// time:
//
//   Stir   circle the hand round the contact point: the hemisphere leans and
//          precesses. Aim the circle's centre a little off the contact and
//          the helix drifts, about 45 degrees from the aim, to the side the
//          hemisphere turns; so aim that far the other way, and less the
//          nearer the target.
//   Land   once the hemisphere would stand on the target if it were rolled
//          upright, let the stir die away over a second or two.
//   Settle then hold the hand still over that spot and nudge it while the
//          contact stays off; stir again if it rolls away, or if it will not
//          settle after a while.
//   Turn   a task that asks for a heading the HUD says is not reached yet:
//          stir round the contact with no aim, anticlockwise to turn it
//          clockwise and the other way round, until the heading is well
//          inside its band; then land and settle as above.
//   Lean   a task that asks for a lean: hold the hand off the contact the way
//          the lean should go, further while the lean falls short. A target
//          near enough that may be reached leaning (nothing asks for upright):
//          hold the hand over the target and nudge it until the contact
//          rolls onto it.
//
// "Where it would stand upright" (c_up, autopilot/UprightContact.h) is read
// off what the screen shows: the contact point and the lean on the tilt
// gauge; which way it turns is the spin the HUD shows. The figures are the
// technique's as taught, the same for every body, not tuned per level, and
// nothing here is tuned to the game's cues (docs/HUMAN_MODEL.md).

#include "engine/human/MotorPlan.h"
#include "engine/human/ScreenView.h"

namespace hemiroll::human {

struct TechniqueDef {
  double stirRadius = 0.003;      // [m]
  double stirRate = M_PI;         // half a turn a second [rad/s]
  double aimAngle = M_PI / 4;     // how far the aim leads the drift [rad]
  double aimGain = 0.25;          // aim offset per metre of c_up error [-]
  double aimLimit = 0.002;        // [m]
  double spinLag = 1.0;           // how long the turning is watched to tell its sense [s]
  double landReach = 0.002;       // c_up this close to the target: land [m]
  double fadeRate = 0.002;        // how fast the stir dies away [m/s]
  double holdReach = 0.002;       // settling: the hold goes this far from c_up towards the target [m]
  double nudgeGain = 0.1;         // settling: the hold moves this fraction of the contact's error [-]
  double restirReach = 0.006;     // c_up this far while settling: stir again [m]
  double settlePatience = 10.0;   // settling this long without success: stir again [s]
  double leanGain = 0.5;          // leaning: the hold moves this fraction of the lean's error (as R sin) [-]
  double leanReach = 0.01;        // a target this near, with nothing asking for upright, is reached leaning [m]
  // Turning: rolling the contact round a loop turns the hemisphere the other
  // way about the vertical (an anticlockwise stir, a clockwise turn).
  double turnInside = 0.5;        // stir until the heading is this fraction of its band from the target [-]
  double turnOutside = 0.9;       // settling: stir again once it is this fraction of the band off [-]
};

class Technique {
 public:
  enum class Phase { Stir, Land, Settle, Lean, Turn };

  Technique(const TechniqueDef& def, double radius) : def_(def), radius_(radius) {}

  // One decision from one view; `interval` is the time until the next [s].
  Movement decide(const ScreenView& view, double interval);
  Phase phase() const { return phase_; }
  // The target is near enough to lean onto and nothing asks for upright.
  bool reachLeaning(const ScreenView& view) const;

 private:
  Movement stir(const ScreenView& view, const physics::Vec2& error, double radius) const;
  Movement lean(const ScreenView& view);
  Movement leanOnto(const ScreenView& view);
  Movement settle(const ScreenView& view, const physics::Vec2& upright, const physics::Vec2& target);
  // Holding still the technique's way: over the target when it may be
  // reached leaning, else over c_up moved towards the target.
  Movement hold(const ScreenView& view);
  // A heading to reach with nothing to carry: the stir that turns it.
  Movement turn(const ScreenView& view, double radius);

  TechniqueDef def_;
  double radius_;
  Phase phase_ = Phase::Stir;
  int stage_ = -1;
  double fading_ = 0.0;      // the stir's radius while it dies away [m]
  double spinSeen_ = 0.0;    // the turning, watched over spinLag [rad/s]
  double settledAt_ = 0.0;   // [s]
  double turnSense_ = 1.0;   // the turning stir's sense: +1 anticlockwise
  physics::Vec2 nudge_ = physics::Vec2::Zero();
};

// Where the contact would be if the hemisphere were rolled straight back
// upright, from what the screen shows (the contact and the lean) [m].
physics::Vec2 uprightContactSeen(const ScreenView& view, double radius);

}  // namespace hemiroll::human
