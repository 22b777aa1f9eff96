#include "tests/game/support/TinySweep.h"

#include "engine/script/SweepLoader.h"

namespace hemiroll::test {

const char* const kTinySweep = R"(return {
  description = "tiny",
  duration = 12,
  axes = {
    { param = "k", values = { 7, 8, 10 } },
    { param = "Omega", range = { from = -0.6, to = -0.3, count = 3 } },
  },
})";

const char* const kTippingSweep = R"(return {
  start = "rest",
  duration = 3,
  axes = {
    { param = "k", values = { 8, 16 } },
    { param = "Omega", values = { -0.3141592653589793, -1.0 } },
  },
})";

task::SweepDef sweepOf(const std::string& source) { return script::SweepLoader().loadSource(source, "tiny.lua"); }

game::SweepPartReport runSweepInto(const std::string& source, const std::filesystem::path& dir, game::SweepShard shard,
                                   int threads, int laneWidth) {
  game::SweepPartRequest request;
  request.def = sweepOf(source);
  request.specFile = "tiny.lua";
  request.shard = shard;
  request.outDir = dir;
  request.threads = threads;
  request.laneWidth = laneWidth;
  request.program = "hemiroll test";
  return game::runSweepPart(request);
}

}  // namespace hemiroll::test
