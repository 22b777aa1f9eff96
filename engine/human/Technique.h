#pragma once
// What a person who has learned the technique in words (the paper's, Sec.
// 4.2, as the tutorials put it) does, deciding from one delayed view at a
// time:
//
//   Stir   swirl the hand round where the hemisphere would stand upright
//          (c_up, watched over a turn), a turn every two seconds: circles
//          as big as keep the tilt gauge at about 10 degrees, aimed a
//          little off that spot, a quarter turn from the way it should go,
//          to the side the hemisphere turns. The helix carries c_up along.
//   Land   once c_up is on the target, let the swirl die away over a
//          second or two.
//   Settle then hold the hand still over that spot and nudge it while the
//          contact stays off; stir again if it rolls away, or if it will not
//          settle after a while.
//   Brake  settled but still turning (the HUD's spin): swirl a second in
//          the sense it turns, then let that die away; a swirl leaves a
//          turn the other way as it dies away, and that one cancels what
//          was left.
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
  double stirRadius = 0.003;      // the first swirl's size, and the turning stir's [m]
  double stirRate = M_PI;         // half a turn a second [rad/s]
  double swirlTilt = 0.17;        // the swirl grows or shrinks to keep this tilt (about 10 degrees) [rad]
  double swirlGrowth = 0.5;       // how fast its size follows the tilt: log-size per second at a full tilt error [1/s]
  double swirlMin = 0.002;        // [m]
  double swirlMax = 0.015;        // [m]
  double uprightLag = 2.0;        // how long c_up and the tilt are watched (a swirl's turn) [s]
  double aimAngle = M_PI / 2;     // how far the aim leads the drift [rad]
  double aimGain = 0.5;           // aim offset per metre of c_up error [-]
  double aimLimit = 0.006;        // [m]
  double spinLag = 1.0;           // how long the turning is watched to tell its sense [s]
  double landReach = 0.002;       // c_up this close to the target: land [m]
  double fadeTime = 1.5;          // how long the swirl takes to die away [s]
  double brakeAbove = 0.03;       // settled and turning faster than this: brake [rad/s]
  double brakeBand = 0.5;         // ... or than this fraction of the spin's band on the HUD, if less [-]
  double brakeWait = 1.0;         // settled this long before braking [s]
  double brakeTime = 1.0;         // the braking swirl's length, before it dies away [s]
  double brakeRest = 2.0;         // at least this long between two brakes [s]
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
  enum class Phase { Stir, Land, Settle, Lean, Turn, Brake };

  Technique(const TechniqueDef& def, double radius) : def_(def), radius_(radius) {}

  // One decision from one view; `interval` is the time until the next [s].
  Movement decide(const ScreenView& view, double interval);
  Phase phase() const { return phase_; }
  // The target is near enough to lean onto and nothing asks for upright.
  bool reachLeaning(const ScreenView& view) const;

 private:
  Movement stir(const physics::Vec2& error, double radius, double sense) const;
  // Watching: c_up and the tilt over a swirl's turn, and the swirl's size.
  void watch(const ScreenView& view, double interval);
  // How fast it may turn, settled, before the person brakes [rad/s].
  double brakeAbove(const ScreenView& view) const;
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
  physics::Vec2 uprightSeen_ = physics::Vec2::Zero();  // c_up watched over uprightLag [m]
  double tiltSeen_ = 0.0;    // the tilt watched over uprightLag [rad]
  bool watching_ = false;
  double swirl_ = 0.0;       // the swirl's size now [m]
  double brakeSense_ = 1.0;  // the braking swirl's sense: +1 anticlockwise
  double brakeSize_ = 0.0;   // the braking swirl's size [m]
  double brakeEnds_ = 0.0;   // when the braking swirl starts to die away [s]
  double brakedAt_ = -1e9;   // when the last brake ended [s]
  double turnSense_ = 1.0;   // the turning stir's sense: +1 anticlockwise
  physics::Vec2 nudge_ = physics::Vec2::Zero();
};

// Where the contact would be if the hemisphere were rolled straight back
// upright, from what the screen shows (the contact and the lean) [m].
physics::Vec2 uprightContactSeen(const ScreenView& view, double radius);

}  // namespace hemiroll::human
