#pragma once
// Cross-entropy search over a landing shape (HelixPolicy.h): sample shapes
// about a mean, keep the best few by their score, refit the mean and the
// spread to them, repeat; stop at the first shape that succeeds. The caller
// scores a shape (Autopilot: a rollout of the landing through the model).
//
// Deterministic: the draws are splitmix64 + Box-Muller from `seed`, the same
// on every standard library.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "engine/autopilot/HelixPolicy.h"

namespace hemiroll::autopilot {

struct LandingSearchDef {
  int population = 32;   // shapes per round (the first is the mean itself)
  int elites = 6;        // kept to refit the mean and spread
  int rounds = 8;
  double spread = 0.002; // first spread of every knot coordinate [m]
  std::uint64_t seed = 0;
  // Shapes handed to one call of a ScoreShapes (the autopilot rolls them out
  // together, one per SIMD lane). The search's result does not depend on it.
  int batch = 1;
  // Asked before each call of the scorer (each shape, or each batch); true
  // ends the search with nothing (real time: a plan must be ready when its
  // moment comes). Empty: never.
  std::function<bool()> outOfTime;
};

struct ShapeScore {
  bool success = false;  // the model says this landing ends inside every band
  double cost = 1e30;    // lower is better (used while none succeeds)
};

using ScoreShape = std::function<ShapeScore(const LandingShape&)>;
// Scores of several shapes, in their order (at most def.batch at a time).
using ScoreShapes = std::function<std::vector<ShapeScore>(const std::vector<LandingShape>&)>;

// The first shape that succeeds, or nothing after `rounds` rounds (or when
// out of time). The shapes are drawn and judged in one order whatever the
// batch, so the result is the same for every batch size.
std::optional<LandingShape> searchLandingShape(const LandingSearchDef& def, const ScoreShapes& score);
// One shape a call (the batch is 1).
std::optional<LandingShape> searchLandingShape(const LandingSearchDef& def, const ScoreShape& score);

}  // namespace hemiroll::autopilot
