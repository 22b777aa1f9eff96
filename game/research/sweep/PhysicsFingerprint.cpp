#include "game/research/sweep/PhysicsFingerprint.h"

#include "engine/record/ContentHash.h"
#include "game/research/sweep/PointMeasurement.h"
#include "game/research/sweep/SweepGrid.h"
#include "game/research/sweep/SweepTable.h"

namespace hemiroll::game {

std::string physicsFingerprintOf(const task::SweepDef& base) {
  std::string rows;
  for (const char* integrator : {"rk4", "dop853"}) {
    task::SweepDef def = base;
    def.start = task::SweepStart::Rest;
    def.duration = 4.0;  // from rest the paper's drive is chaotic: ulps become millimetres by then
    def.integrator = integrator;  // dop853 at the base spec's tolerance
    def.axes = {task::SweepAxis{task::SweepParam::k, {def.rose.k}, false}};
    const SweepGrid grid(def);
    const SweepPoint point = grid.point(0);
    rows += sweepRow(point, measurePoint(grid, point));
  }
  return record::contentHash(rows);
}

const std::string& physicsFingerprint() {
  static const std::string fingerprint = physicsFingerprintOf(task::SweepDef{});
  return fingerprint;
}

}  // namespace hemiroll::game
