#pragma once
// A protocol expanded into the flat list of trials a session runs, in
// order. Deterministic: the same protocol and seed give the same plan on
// every machine (EngineRandom, xoshiro256**).
//
// Per block, in block order: the conditions repeated `repetitions` times
// (pass 1: conditions 1..n, pass 2: 1..n, ...); a randomised block's trials
// are then shuffled together (Fisher-Yates). Each block draws its own
// generator from a master generator seeded with the session's seed, one
// draw per block whether it shuffles or not, so a block's order and seeds do
// not depend on whether the blocks before it are randomised. Every trial
// gets a seed of its own from its block's generator (0 .. 2^63 - 1, a Lua
// integer): the level's hemiroll.random and the bot's.

#include <cstdint>
#include <string>
#include <vector>

#include "engine/task/ProtocolDef.h"

namespace hemiroll::task {

struct PlannedTrial {
  int index = 0;          // 1-based position in the session
  int block = 0;          // 1-based place of its block in this plan's order
  int definedBlock = 0;   // 1-based block of the protocol file (differs from `block` under counterbalancing)
  int trialInBlock = 0;   // 1-based position in its block
  int repetition = 0;     // 1-based pass through the block's conditions
  int condition = 0;      // 1-based condition of the block
  std::uint64_t seed = 0; // the trial's seed
};

struct ProtocolPlan {
  std::uint64_t seed = 0;             // the seed it was expanded with
  std::vector<PlannedTrial> trials;

  // The trial's block and condition in `protocol` (the one it was expanded from).
  static const BlockDef& blockOf(const ProtocolDef& protocol, const PlannedTrial& trial);
  static const ConditionDef& conditionOf(const ProtocolDef& protocol, const PlannedTrial& trial);
  // The break to show before `trial`: the break_after written at the
  // previous place when the trial opens a block (breaks belong to the places
  // between blocks, so counterbalancing moves none); nullptr otherwise.
  static const BreakDef* breakBefore(const ProtocolDef& protocol, const PlannedTrial& trial);
};

// `order`: the participant's block order (1-based, ProtocolDef::blockSequence).
// A block's trial order and seeds do not depend on its place: each block's
// generator is drawn in the file's block order.
ProtocolPlan expandProtocol(const ProtocolDef& protocol, std::uint64_t seed, int order = 1);

}  // namespace hemiroll::task
