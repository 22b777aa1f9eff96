// Test helper for TrialRecorderCrashTest: records one short trial to the end
// (files finished, a results row), then records a second one in real time,
// one row per millisecond through the ring and the writer thread, for
// `seconds` (default 3), unless it is killed first - which is the point.
// Row k of the second trial has tick k and time = the steady clock
// (CLOCK_MONOTONIC, shared with the test process) when it was pushed, so the
// test can tell how much of the run reached the disk before the kill.
//
// usage: record_crash_helper DIR [seconds]

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

#include "engine/record/Record.h"

using namespace hemiroll;

namespace {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: record_crash_helper DIR [seconds]\n");
    return 2;
  }
  const double seconds = argc > 2 ? std::atof(argv[2]) : 3.0;
  try {
    const record::RecordingSession session(argv[1], {"crash", "1"});

    record::TrialMeta done;
    done.trialId = "finished";
    done.recordEvery = 1;
    record::TrialRecorder first = session.beginTrial(done);
    for (std::uint64_t k = 1; k <= 300; ++k) {
      haptics::RecordRow row;
      row.tick = k;
      row.time = 0.001 * static_cast<double>(k);
      row.state[0] = static_cast<double>(k);
      first.push(row);
    }
    record::TrialEnd end;
    end.outcome = "success";
    first.finish(end);
    session.appendResult(record::RecordingSession::resultOf(first, end, 0.3));

    record::TrialMeta live;
    live.trialId = "interrupted";
    live.recordEvery = 1;
    record::TrialRecorder second = session.beginTrial(live);
    auto ring = std::make_unique<haptics::RecordRing>();
    second.startWriter(*ring);
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t k = 1;; ++k) {
      haptics::RecordRow row;
      row.tick = k;
      row.time = steadySeconds();
      row.state[0] = static_cast<double>(k);
      ring->push(row);
      const auto next = start + std::chrono::milliseconds(k);
      if (next - start > std::chrono::duration<double>(seconds)) break;
      std::this_thread::sleep_until(next);
    }
    second.finish(end);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "record_crash_helper: %s\n", e.what());
    return 1;
  }
  return 0;
}
