#pragma once
// The paper's strategy (Sec. 4.2) as a feedback law on the measured state,
// one proxy pose per servo tick. Three phases:
//
//   Travel  the proxy circles a steering point just beside the contact point
//           (radius `amplitude`, rate `rate`): the hemisphere tilts and
//           precesses on a steady helix. Offsetting the steering point from
//           the contact by `steerGain` x (c_up error turned by `steerAngle`)
//           makes the helix drift, and the drift carries c_up (UprightContact.h)
//           towards the target: measured on the paper's model, about 1 cm/s
//           for a 1 mm offset, at an angle of about 1 rad from the offset.
//   Land    the circling fades out at `landRate`; steering goes on.
//   Settle  the proxy glides at `glideSpeed` to a point above the landing
//           point (c_up, moved towards the target as far as the bands on p
//           and u_co allow): the hemisphere rolls straight under it and
//           stands upright there, since a straight roll keeps c_up. Near
//           rest a regulator (SettleRegulator.h) takes the proxy and holds
//           the rest leaning from c_up to the landing point, still.
//
// Deterministic and cheap (a few flops per tick); copyable, so that the
// planner can roll copies forward through the model (Autopilot.h).

#include <array>

#include "engine/autopilot/Goal.h"
#include "engine/autopilot/SettleRegulator.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/StateLayout.h"

namespace hemiroll::autopilot {

struct HelixParams {
  double amplitude = 0.003;    // radius of the proxy's circle [m]
  double rate = 3.14159;       // circling rate [rad/s]; the sign is the sense
  double steerAngle = 1.0;     // the steering offset is the c_up error turned by this [rad]
  double steerGain = 1.0;      // steering offset per metre of c_up error [-]
  double steerLimit = 0.0015;  // largest steering offset [m]
  double landRate = 0.003;     // fade of the circle's radius when landing [m/s]
  double glideSpeed = 0.005;   // proxy speed while settling [m/s]
  // While settling, the proxy's goal creeps by settleGain x (landing point -
  // contact) per second: on the paper's masses the contact stands right under
  // a still proxy (m_p g / k_r ~ R), on others this integral finds the offset.
  double settleGain = 1.5;     // [1/s]
  // While landing and settling the proxy may also circle against the
  // measured spin, radius despinGain x |w_z| (at most `amplitude`), since
  // circling makes spin in its own sense. A landing candidate after the plain
  // ones; of the shipped levels only the full orientation challenge lands
  // with it (36.0 s with it, 44.9 s without, measured before the settle
  // integral was gated by the contact's band; 28.4 s with it since); taking spin out is
  // mostly the landing shape's job. 0 turns it off.
  double despinGain = 0.0;     // [m s/rad]
  // The coupling made stiffer by the hand itself: the proxy is put
  // `stiffen` times its offset from the mass point further out, so the
  // spring and damper act as (1 + stiffen) times theirs (Autopilot.h:
  // chosen from the body and coupling). 0: as the level has them.
  double stiffen = 0.0;        // [-]
};

enum class HelixPhase { Travel, Land, Settle };

// What the law did on its last tick, in a player's terms (the game's hint
// at a person's bandwidth, game/trial/HintCoach): the circle the proxy is
// on, or the point it glides to.
struct HelixMotion {
  HelixPhase phase = HelixPhase::Travel;
  physics::Vec2 centre = physics::Vec2::Zero();  // the circle's centre (travel, land) [m]
  double radius = 0.0;                           // [m]
  double rate = 0.0;                             // [rad/s]
  physics::Vec2 goal = physics::Vec2::Zero();    // where the proxy glides to (settle) [m]
};

// A shape added to the proxy from the moment landing starts: offsets at
// knots `spacing` apart, linear between them, fading to zero after the last.
// The planner tunes them (Autopilot::refineLanding) when no plain landing
// ends inside the bands: what it must undo is mostly spin.
struct LandingShape {
  static constexpr int kKnots = 8;
  // Eigen vectors are not zeroed by value-initialisation: every knot is set.
  std::array<physics::Vec2, kKnots> knots = zeroKnots();  // [m]
  double spacing = 0.4;                       // [s]
  physics::Vec2 at(double t) const;           // offset t seconds into the landing [m]

  static std::array<physics::Vec2, kKnots> zeroKnots() {
    std::array<physics::Vec2, kKnots> k;
    k.fill(physics::Vec2::Zero());
    return k;
  }
};

class HelixPolicy {
 public:
  HelixPolicy(const physics::ModelConstants& constants, const HelixParams& params, double dt);

  void setGoal(const Goal& goal);
  // Start from the current proxy (the first glide starts there).
  void startAt(const physics::Vec3& proxy);
  void land(double landRate, double despinGain = 0.0, const LandingShape& shape = {});
  void travel();
  // The spin brake (SpinBrake.h): circle the contact at `amplitude` and
  // `rate` (the sign is the sense) with no steering for `lock` seconds, then
  // stop dead and settle.
  void brake(double amplitude, double rate, double lock);
  bool braking() const { return brakeLeft_ > 0.0; }
  // A new landing shape from now on, the phase unchanged (a landing corrected
  // on its way).
  void reshape(const LandingShape& shape);
  void settleNow();
  // Settle with the regulator (SettleRegulator.h) where it has a gain:
  // the proxy is moved to hold the rest rather than glided over it.
  void setSettleGain(const SettleGain& gain) { settleGain_ = gain; }
  const SettleGain& settleGain() const { return settleGain_; }
  // Only where the proxy is the autopilot's own: under guidance or a hint
  // another hand holds it, and the regulator's model is not the plant.
  void enableRegulator(bool on) { regulatorOn_ = on; }
  // Whether a stage that asks for a lean (and no contact point) is held
  // there by the regulator, or glided to as before (Autopilot.cpp, takeGoal:
  // not in a stage with a psi band and no hold).
  void regulateLean(bool on) { regulateLean_ = on; }

  // The proxy for the next tick, from the state after the last one.
  physics::Vec3 proxyFor(const physics::ForceDrivenState& x);

  HelixPhase phase() const { return phase_; }
  const HelixMotion& motion() const { return motion_; }
  HelixParams& params() { return params_; }
  const HelixParams& params() const { return params_; }
  // Where the contact would end after landing now (above c_up, nudged to the target).
  physics::Vec2 landingPoint(const physics::Vec2& upright) const;

 private:
  physics::Vec2 contactTarget() const;
  // The contact's distance from its target in units of its band (the larger
  // of u_a's and v_a's; 0 when neither is set).
  double contactBandError(const physics::ForceDrivenState& x) const;
  physics::Vec3 despin(const physics::ForceDrivenState& x);
  physics::Vec2 detour(const physics::Vec2& contact, const physics::Vec2& land);
  physics::Vec3 stiffened(const physics::Vec3& proxy, const physics::ForceDrivenState& x) const;
  // A stage that asks for a lean (u_co) and no contact point: the settle
  // goal that holds the hemisphere at that lean (HelixPolicy.cpp).
  bool leansOnly() const;
  physics::Vec3 leanGoal(const physics::ForceDrivenState& x);
  bool nearRest(const physics::ForceDrivenState& x, double tilt) const;
  // The regulated settle: the rest with horizontal face normal `lean`
  // (from c_up to the landing point, or the lean a stage asks for); `goal`
  // is what the hint shows.
  physics::Vec3 regulatedSettle(const physics::ForceDrivenState& x, const physics::Vec2& lean,
                                const physics::Vec2& goal);

  const physics::ModelConstants* constants_;
  HelixParams params_;
  double dt_;
  Goal goal_;
  double landReach_ = 0.0;  // how far from c_up the contact may end [m]
  HelixPhase phase_ = HelixPhase::Travel;
  double phaseAngle_ = 0.0, radius_ = 0.0;
  physics::Vec3 last_ = physics::Vec3::Zero();
  physics::Vec2 settleOffset_ = physics::Vec2::Zero();  // integral of the settle loop [m]
  LandingShape shape_;
  double despinAngle_ = 0.0;
  double landingTime_ = 0.0;  // since landing started [s]
  double brakeLeft_ = 0.0;    // the brake's circling still to go (0: not braking) [s]
  double brakeAmplitude_ = 0.0, brakeRate_ = 0.0;
  int detourZone_ = -1;       // the zone being passed (-1: none)
  physics::Vec2 waypoint_ = physics::Vec2::Zero();
  HelixMotion motion_;
  SettleGain settleGain_;
  physics::Vec3 given_ = physics::Vec3::Zero();  // the proxy the last tick gave (after every addition)
  physics::Vec3 added_ = physics::Vec3::Zero();  // what the despin circle and the shape added to it
  bool regulating_ = false;                      // the regulator has the proxy (its path starts at given_)
  bool regulatorOn_ = true;
  bool regulateLean_ = true;
};

}  // namespace hemiroll::autopilot
