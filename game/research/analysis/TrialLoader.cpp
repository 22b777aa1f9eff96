#include "game/research/analysis/TrialLoader.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <string_view>
#include <system_error>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/files/LineReader.h"
#include "engine/files/PrintableName.h"
#include "engine/physics/StateLayout.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "game/research/analysis/AnalysisInputError.h"
#include "game/research/analysis/SimCsvReader.h"

namespace hemiroll::game {

namespace {

namespace fs = std::filesystem;

// Either header is a few hundred bytes.
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

// The header line, read through the checked reader: a FIFO, a device or a
// file without a line end in its first 64 KiB is refused here.
std::string firstLine(const fs::path& path) {
  try {
    files::CheckedFile file(path, files::kSampleTable);
    files::LineReader lines(file, kMaxHeaderBytes);
    std::string_view line;
    if (!lines.next(line)) return "";
    return std::string(line);
  } catch (const files::FileReadError& e) {
    throw AnalysisInputError(e.what());
  }
}

// A recording's rows straight into the columns, a line at a time: memory
// holds the columns, never the file or its rows.
TrialData readRecording(const fs::path& path) {
  record::TrialMeta meta;
  record::SidecarStatus status;
  TrialData trial;
  trial.source = files::printablePath(path);
  trial.kind = "recording";
  bool cut = false;
  std::uint64_t rows = 0;
  namespace slot = physics::force_slot;
  try {
    record::RecordingReader::loadSidecar(path, meta, status);
    cut = record::RecordingReader::forEachRow(path, {.allowTruncatedTail = true}, [&](const haptics::RecordRow& row) {
      ++rows;
      trial.time.push_back(row.time);
      trial.massX.push_back(row.state[slot::x_p]);
      trial.massY.push_back(row.state[slot::y_p]);
      trial.contactX.push_back(row.state[slot::u_a]);
      trial.contactY.push_back(row.state[slot::v_a]);
      trial.psi.push_back(row.state[slot::psi]);
      trial.proxyX.push_back(row.proxyPosition[0]);
      trial.proxyY.push_back(row.proxyPosition[1]);
      trial.guideX.push_back(row.guidanceForce[0]);
      trial.guideY.push_back(row.guidanceForce[1]);
      trial.guideZ.push_back(row.guidanceForce[2]);
      trial.proxyVX.push_back(row.proxyVelocity[0]);
      trial.proxyVY.push_back(row.proxyVelocity[1]);
      trial.proxyVZ.push_back(row.proxyVelocity[2]);
      trial.handX.push_back(row.handForce[0]);
      trial.handY.push_back(row.handForce[1]);
      trial.handZ.push_back(row.handForce[2]);
    });
  } catch (const record::RecordError& e) {
    throw AnalysisInputError(e.what());
  }
  if (status.complete && status.rows != rows)
    throw AnalysisInputError(trial.source + ": holds " + std::to_string(rows) + " rows, its sidecar says " +
                             std::to_string(status.rows));
  if (cut) trial.notes.push_back("an interrupted recording: its cut last line is not used");
  if (!status.complete && !cut) trial.notes.push_back("the sidecar says the trial did not finish");
  if (trial.time.empty()) throw AnalysisInputError(trial.source + ": line 2: no rows after the header");
  return trial;
}

TrialData readFile(const fs::path& path) {
  const std::string header = firstLine(path);
  const std::string recordingHeader = record::CsvRowFormat::header();
  TrialData trial;
  if (header + "\n" == recordingHeader) {
    trial = readRecording(path);
  } else if (isSimCsvHeader(header)) {
    trial = readSimCsv(path);
  } else {
    throw AnalysisInputError(files::printablePath(path) +
                             ":1: neither a trial recording (time_s,tick,...) nor a `hemiroll sim` CSV "
                             "(t,x_p,y_p,...)");
  }
  trial.id = files::printable(path.stem().native());
  return trial;
}

std::vector<fs::path> trialsIn(const fs::path& dir) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file(ec) || entry.path().extension() != ".csv") continue;
    // The session's summary and an earlier analysis written into the folder are not trials.
    if (entry.path().filename() == "results.csv" || entry.path().filename() == "analysis.csv") continue;
    found.push_back(entry.path());
  }
  if (ec) throw AnalysisInputError(files::printablePath(dir) + ": cannot be listed (" + ec.message() + ")");
  std::sort(found.begin(), found.end());
  if (found.empty()) throw AnalysisInputError(files::printablePath(dir) + ": holds no trial CSV");
  return found;
}

}  // namespace

std::vector<TrialData> loadTrials(const std::vector<std::string>& paths) {
  std::vector<TrialData> trials;
  std::set<std::string> ids;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (!fs::exists(p, ec) && !fs::is_symlink(p, ec))
      throw AnalysisInputError(files::printable(p) + ": no such file or folder");
    const std::vector<fs::path> found = fs::is_directory(p, ec) ? trialsIn(p) : std::vector<fs::path>{p};
    for (const fs::path& f : found) {
      TrialData trial = readFile(f);
      const std::string base = trial.id;
      for (int n = 2; ids.count(trial.id) > 0; ++n) trial.id = base + "-" + std::to_string(n);
      ids.insert(trial.id);
      trials.push_back(std::move(trial));
    }
  }
  return trials;
}

}  // namespace hemiroll::game
