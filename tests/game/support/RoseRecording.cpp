#include "tests/game/support/RoseRecording.h"

#include "engine/physics/StateLayout.h"
#include "engine/record/TrialRecorder.h"
#include "tests/analysis/support/Synthetic.h"

namespace hemiroll::test {

std::filesystem::path writeRoseRecording(const std::filesystem::path& dir, const std::string& id, int rows,
                                         bool finished) {
  const double duration = (rows - 1) / 100.0;
  const Planar mass = rose(0.015, 0.008, 8, -M_PI / 10, duration, 100.0);
  const Planar contact = trochoidArc(0.05, 0.002, 0.002, 9 * M_PI / 10, 0.0, duration, 100.0);
  record::TrialMeta meta;
  meta.trialId = id;
  meta.levelName = "synthetic rose";
  record::TrialRecorder recorder(dir, meta);
  namespace slot = physics::force_slot;
  for (int i = 0; i < rows; ++i) {
    haptics::RecordRow row;
    row.time = mass.t[static_cast<std::size_t>(i)];
    row.tick = static_cast<std::uint64_t>(10 * (i + 1));
    row.state[slot::x_p] = mass.x[static_cast<std::size_t>(i)];
    row.state[slot::y_p] = mass.y[static_cast<std::size_t>(i)];
    row.state[slot::u_a] = contact.x[static_cast<std::size_t>(i)];
    row.state[slot::v_a] = contact.y[static_cast<std::size_t>(i)];
    row.state[slot::psi] = -0.1 * row.time;
    recorder.push(row);
  }
  const std::filesystem::path csv = recorder.csvPath();
  if (finished) {
    record::TrialEnd end;
    end.outcome = "success";
    recorder.finish(end);
  }
  return csv;  // unfinished: the destructor flushes and leaves the sidecar incomplete
}

}  // namespace hemiroll::test
