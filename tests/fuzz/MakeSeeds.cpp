// The seed corpora of the fuzz targets whose inputs are this program's own
// outputs, written by this program's own writers (so they follow every
// format change): `fuzz_make_seeds DIR` fills DIR/<target>/ with small valid
// files - a replay log, a trial CSV and its sidecar, settings.json, a sweep
// part's manifest and CSV, UDP datagrams both ways. The Lua targets use the
// shipped levels, scenarios, protocols, sweep specs and bots instead.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/haptics/UdpProtocol.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/ReplayLogger.h"
#include "engine/record/Sidecar.h"
#include "engine/script/SweepLoader.h"
#include "game/ui/settings/SettingsFile.h"
#include "game/research/sweep/SweepManifest.h"
#include "game/research/sweep/SweepSpecJson.h"
#include "game/research/sweep/SweepTable.h"

namespace fs = std::filesystem;
using namespace hemiroll;

namespace {

void write(const fs::path& file, const std::string& bytes) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << bytes;
}

haptics::RecordRow row(std::uint64_t tick) {
  haptics::RecordRow r;
  r.tick = tick;
  r.time = 0.001 * static_cast<double>(tick);
  r.state[7] = 1e-4 * static_cast<double>(tick);
  r.proxyPosition = {0.0, 0.0, 0.04};
  r.guidanceForce = {0.1, -0.2, 0.0};
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_make_seeds DIR\n");
    return 2;
  }
  const fs::path dir = argv[1];
  // Made afresh every run: the replay logger never overwrites a log, and a
  // seed left from an older build's format would test nothing.
  fs::remove_all(dir);

  // A replay log: 20 ticks and an engage command.
  {
    fs::create_directories(dir / "replay_log");
    record::ReplayHeader header;
    header.softwareVersion = "fuzz";
    header.levelHash = "fnv1a-0000000000000000";
    header.deviceKind = "mouse";
    record::ReplayLogger log(dir / "replay_log" / "twenty-ticks.hrr", header);
    haptics::AppliedCommand engage;
    engage.tick = 1;
    engage.command.kind = haptics::ServoCommandKind::Engage;
    log.push(engage);
    for (std::uint64_t t = 1; t <= 20; ++t) {
      haptics::TickInput in;
      in.tick = t;
      in.position = {1e-4 * static_cast<double>(t), 0.0, 0.04};
      in.newPath = t == 10;
      log.push(in);
    }
    log.finish();
  }

  // A trial's CSV (five rows, and one cut short) and its sidecar.
  std::string csv = record::CsvRowFormat::header();
  for (std::uint64_t t = 10; t <= 50; t += 10) record::CsvRowFormat::append(row(t), csv);
  write(dir / "trial_csv" / "five-rows.csv", csv);
  write(dir / "trial_csv" / "cut-short.csv", csv.substr(0, csv.size() - 7));
  record::TrialMeta meta;
  meta.guidance.kind = haptics::GuidanceKind::Autopilot;
  meta.guidance.stiffness = 300.0;
  meta.extra = {{"condition", "guided"}};
  record::SidecarStatus status;
  write(dir / "sidecar" / "started.json", record::Sidecar::toJson(meta, status));
  record::TrialEnd end;
  end.outcome = "success";
  status.complete = true;
  status.end = end;
  write(dir / "sidecar" / "finished.json", record::Sidecar::toJson(meta, status));

  // settings.json: the defaults.
  write(dir / "settings" / "defaults.json", game::settingsJson(game::Settings{}));

  // A sweep part: a manifest of a shipped spec and a CSV of its columns.
  {
    const task::SweepDef spec =
        script::SweepLoader().loadFile(HEMIROLL_SOURCE_DIR "/levels/sweeps/rose_k_omega.lua");
    game::SweepManifest m;
    m.program = "hemiroll fuzz";
    m.specFile = "rose_k_omega.lua";
    m.specHash = game::specHash(spec);
    m.specJson = game::specJson(spec);
    m.pointsTotal = 4;
    m.pointCount = 4;
    m.csv = "part.csv";
    write(dir / "sweep_part" / "manifest.json", game::manifestJson(m));
    std::string table;
    for (std::size_t i = 0; i < game::sweepColumns().size(); ++i) table += (i ? "," : "") + game::sweepColumns()[i];
    write(dir / "sweep_part" / "part.csv", table + "\n");
  }

  // UDP datagrams, a state and a force.
  {
    namespace udp = haptics::udp;
    std::string state(udp::kStateSize, '\0'), force(udp::kForceSize, '\0');
    udp::StateMessage s;
    s.sequence = 7;
    s.position = {0.01, 0.0, 0.04};
    udp::encodeState(s, reinterpret_cast<std::uint8_t*>(state.data()));
    udp::ForceMessage f;
    f.answers = 7;
    f.force = {0.5, 0.0, 0.0};
    udp::encodeForce(f, reinterpret_cast<std::uint8_t*>(force.data()));
    write(dir / "udp_datagram" / "state.bin", state);
    write(dir / "udp_datagram" / "force.bin", force);
  }
  return 0;
}
