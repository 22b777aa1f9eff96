// What recording costs (issue 4, history unit):
//   BM_ServoTick/<mode>  one headless servo tick (engaged M3 coupling, RK4,
//     safety, snapshot) with mode 0 = no recording, 1 = a row every 10th
//     tick (100 Hz), 2 = a row every tick plus the replay's input log. The
//     rings are drained every 256 ticks inside the timed loop (a few ns per
//     item), so the difference between the modes bounds what recording adds
//     to the tick.
//   BM_FormatRow / BM_ParseRow  one CSV line of a real row, each way.
//   BM_RecorderPush  TrialRecorder::push into a file in /tmp: formatting,
//     stdio and the 0.5 s flush with fdatasync, amortised (rows/s).
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "engine/haptics/Haptics.h"
#include "engine/haptics/devices/ScriptedDevice.h"
#include "engine/record/Record.h"

namespace {

using namespace hemiroll;
using haptics::Vec3;

haptics::DeviceReading circling(double t) {
  constexpr double kPi = 3.141592653589793, r = 0.005, w = 2.0 * kPi;
  haptics::DeviceReading d;
  d.position = Vec3(r * std::sin(w * t), r * (1.0 - std::cos(w * t)), 0.04);
  d.velocity = Vec3(r * w * std::cos(w * t), r * w * std::sin(w * t), 0.0);
  return d;
}

void BM_ServoTick(benchmark::State& state) {
  const int mode = static_cast<int>(state.range(0));
  auto rows = std::make_unique<haptics::RecordRing>();
  auto inputs = std::make_unique<haptics::InputRing>();
  haptics::ServoLoopDef def;
  def.requestRealtime = false;
  if (mode >= 1) def.recordRing = rows.get();
  def.recordEvery = mode == 2 ? 1 : 10;
  if (mode == 2) def.inputRing = inputs.get();
  haptics::ScriptedDevice device(circling);
  haptics::ServoLoop loop(def, device);
  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);
  loop.runHeadless(1500);  // engaged and ramped in
  haptics::RecordRow row;
  haptics::TickInput in;
  long n = 0;
  for (auto _ : state) {
    loop.tick();
    if (++n % 256 == 0) {
      while (rows->pop(row)) benchmark::DoNotOptimize(row.time);
      while (inputs->pop(in)) benchmark::DoNotOptimize(in.tick);
    }
  }
  state.counters["dropped"] = static_cast<double>(loop.recordDropped() + loop.inputDropped());
}
BENCHMARK(BM_ServoTick)->Arg(0)->Arg(1)->Arg(2);

haptics::RecordRow realRow() {
  auto rows = std::make_unique<haptics::RecordRing>();
  haptics::ServoLoopDef def;
  def.requestRealtime = false;
  def.recordRing = rows.get();
  def.recordEvery = 1;
  haptics::ScriptedDevice device(circling);
  haptics::ServoLoop loop(def, device);
  haptics::ServoCommand engage;
  engage.kind = haptics::ServoCommandKind::Engage;
  loop.post(engage);
  loop.runHeadless(1500);
  haptics::RecordRow row, last;
  while (rows->pop(row)) last = row;
  return last;
}

void BM_FormatRow(benchmark::State& state) {
  const haptics::RecordRow row = realRow();
  std::string line;
  for (auto _ : state) {
    line.clear();
    record::CsvRowFormat::append(row, line);
    benchmark::DoNotOptimize(line.data());
  }
  state.counters["bytes"] = static_cast<double>(line.size());
}
BENCHMARK(BM_FormatRow);

void BM_ParseRow(benchmark::State& state) {
  std::string line;
  record::CsvRowFormat::append(realRow(), line);
  line.pop_back();
  haptics::RecordRow row;
  for (auto _ : state) benchmark::DoNotOptimize(record::CsvRowFormat::parse(line, row));
}
BENCHMARK(BM_ParseRow);

void BM_RecorderPush(benchmark::State& state) {
  const haptics::RecordRow row = realRow();
  const auto dir = std::filesystem::temp_directory_path() / "hemiroll-record-bench";
  std::filesystem::create_directories(dir);
  {
    record::TrialMeta meta;
    meta.trialId = "bench";
    record::TrialRecorder rec(dir, meta);
    for (auto _ : state) rec.push(row);
    rec.finish(record::TrialEnd{});
  }
  state.SetItemsProcessed(state.iterations());
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_RecorderPush);

}  // namespace

BENCHMARK_MAIN();
