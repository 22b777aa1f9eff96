#include "engine/task/ProtocolPlan.h"

#include <utility>

#include "engine/task/EngineRandom.h"

namespace hemiroll::task {

const BlockDef& ProtocolPlan::blockOf(const ProtocolDef& protocol, const PlannedTrial& trial) {
  return protocol.blocks.at(static_cast<std::size_t>(trial.definedBlock - 1));
}

const ConditionDef& ProtocolPlan::conditionOf(const ProtocolDef& protocol, const PlannedTrial& trial) {
  return blockOf(protocol, trial).conditions.at(static_cast<std::size_t>(trial.condition - 1));
}

const BreakDef* ProtocolPlan::breakBefore(const ProtocolDef& protocol, const PlannedTrial& trial) {
  if (trial.trialInBlock != 1 || trial.block < 2) return nullptr;
  const auto& previous = protocol.blocks.at(static_cast<std::size_t>(trial.block - 2)).breakAfter;
  return previous ? &*previous : nullptr;
}

ProtocolPlan expandProtocol(const ProtocolDef& protocol, std::uint64_t seed, int order) {
  ProtocolPlan plan;
  plan.seed = seed;
  EngineRandom master(seed);
  std::vector<std::uint64_t> blockSeeds;
  for (std::size_t b = 0; b < protocol.blocks.size(); ++b) blockSeeds.push_back(master.next());
  const std::vector<int> sequence = protocol.blockSequence(order);
  for (std::size_t place = 0; place < sequence.size(); ++place) {
    const std::size_t b = static_cast<std::size_t>(sequence[place]);
    const BlockDef& block = protocol.blocks[b];
    EngineRandom random(blockSeeds[b]);
    std::vector<PlannedTrial> trials;
    for (int pass = 1; pass <= block.repetitions; ++pass)
      for (std::size_t c = 0; c < block.conditions.size(); ++c) {
        PlannedTrial t;
        t.block = static_cast<int>(place) + 1;
        t.definedBlock = static_cast<int>(b) + 1;
        t.repetition = pass;
        t.condition = static_cast<int>(c) + 1;
        trials.push_back(t);
      }
    if (block.randomise)
      for (std::size_t i = trials.size(); i > 1; --i)
        std::swap(trials[i - 1], trials[static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(i) - 1))]);
    for (std::size_t i = 0; i < trials.size(); ++i) {
      PlannedTrial& t = trials[i];
      t.trialInBlock = static_cast<int>(i) + 1;
      t.index = static_cast<int>(plan.trials.size()) + 1;
      t.seed = random.next() >> 1;  // 0 .. 2^63 - 1: bots receive it as a Lua integer
      plan.trials.push_back(t);
    }
  }
  return plan;
}

}  // namespace hemiroll::task
