#pragma once
// A person at a device, as numbers: how late they see, how often they
// correct, how noisy and how fast their hand is, and what the hand is made
// of. Every default is a figure from the motor-control literature
// (docs/HUMAN_MODEL.md gives the source of each); none is tuned to make the
// game's aids look good. The measuring stick's floor: tests and benchmarks
// use no delay under kMinDelay, no interval under kMinInterval and no less
// noise than kDefaultNoise.

namespace hemiroll::human {

// What the hand holds. A mouse renders no force: nothing pushes the hand.
// A haptic device renders the coupling force: it pushes the hand at once,
// with no neural delay, through the limb's own mechanics. MouseHand: the
// hand moves a mouse (nothing pushes it), and the game simulates a second
// hand between the mouse and the proxy that the force pushes (the game's
// "mouse-hand" feel; the bot, game/trial/HumanBot, runs that hand).
enum class HandDevice { Mouse, Haptic, MouseHand };

const char* handDeviceName(HandDevice device);
// "mouse", "haptic" or "mouse-hand"; false for anything else.
bool parseHandDevice(const char* name, HandDevice& out);

// The hand and arm as a point mass held by a spring and a damper towards
// where the person means it to be (the intent): the muscles' stiffness and
// viscosity about the posture they command.
struct LimbDef {
  double mass = 0.3;        // effective mass of hand, stylus and forearm at the fingertips [kg]
  double stiffness = 300.0; // [N/m]
  double damping = 15.0;    // [N s/m]
};

// The same arm co-contracted: a person holding an unstable load stiffens
// the arm by contracting antagonist muscles together, which resists a push
// mechanically, with no feedback delay (docs/HUMAN_MODEL.md "The arm on a
// force device": Hogan 1984, Burdet et al. 2001). The same mass; the relaxed
// limb's damping ratio kept (15 x sqrt(1000 / 300)).
inline constexpr LimbDef kCoContractedLimb{0.3, 1000.0, 27.4};

struct HumanDef {
  static constexpr double kMinDelay = 0.2;       // [s]
  static constexpr double kMinInterval = 0.25;   // [s]
  static constexpr double kDefaultNoise = 0.1;   // [-]

  // Seeing to acting: a correction uses what the screen showed this long ago.
  double visualDelay = kMinDelay;    // [s]
  // Intermittent control: a new correction at most this often.
  double interval = kMinInterval;    // [s]
  // Signal-dependent motor noise: a move of size s ends with a standard
  // deviation of noise x s (in each of its two directions on the plane);
  // a circle's radius and pace vary by the same fraction.
  double noise = kDefaultNoise;      // [-]
  // What a still hand still does (a floor under the signal-dependent part):
  // standard deviation of where a hold ends [m].
  double steadiness = 0.0002;        // [m]
  // Event-triggered intermittency: a correction is made only when what the
  // person wants differs from what the hand is doing by more than this (the
  // hand's centre or hold point moves, or a circle's radius changes, by more
  // than this), or the kind of movement changes [m].
  double deadZone = 0.0005;          // [m]
  // The fastest the hand is carried to a new place [m/s].
  double maxSpeed = 0.5;             // [m/s]
  LimbDef limb;
  // The arm that holds a force device, which pushes back: co-contracted
  // from taking hold (the paper's subjects had practised a day). A mouse
  // pushes nothing, so there is nothing to stiffen against: `limb` holds it.
  LimbDef coContractedLimb = kCoContractedLimb;
  bool coContracts = true;  // false: the relaxed `limb` on a force device too
  HandDevice device = HandDevice::Mouse;
};

// The limb that holds the device: co-contracted on a force device (unless
// turned off), the relaxed limb on a mouse or the mouse-hand.
inline const LimbDef& holdingLimb(const HumanDef& def) {
  return def.device == HandDevice::Haptic && def.coContracts ? def.coContractedLimb : def.limb;
}

}  // namespace hemiroll::human
