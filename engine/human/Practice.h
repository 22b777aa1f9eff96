#pragma once
// How practice changes the human model (docs/HUMAN_MODEL.md "Learning"):
// the law of practice (Snoddy 1926; Newell & Rosenbloom 1981) says that
// performance improves as a power of the amount of practice, quickly at
// first and ever more slowly. Here what improves is the motor noise, the
// scatter of a move's end (practice makes movements less variable:
// Shmuelof, Krakauer & Mazzoni 2012), from a novice's towards the model's
// own, which stays the floor (HumanDef::noise, the measuring stick's):
//
//   noise(N) = floor + (novice - floor) (N + 1)^(-exponent)
//
// with N the trials practised before this one. Nothing else in the model
// changes with practice: its delay, pace and technique are the same on the
// first trial and the last.

namespace hemiroll::human {

struct PracticeDef {
  // The noise on the first trial, per unit of move size. Ours: twice the
  // floor's 0.1, chosen before any run and not fitted to this game.
  double noviceNoise = 0.2;
  // The power law's exponent. Ours, from the range the law of practice's
  // fits report (well below 1 for most tasks), chosen before any run.
  double exponent = 0.4;
};

// The noise of a person who has practised `trialsBefore` trials; `floor`
// when the novice's is not above it.
double practisedNoise(const PracticeDef& def, double floor, int trialsBefore);

}  // namespace hemiroll::human
