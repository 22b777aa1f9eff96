#include "game/analysis/TrialLoader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <system_error>

#include "engine/physics/StateLayout.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "game/analysis/AnalysisInputError.h"
#include "game/analysis/SimCsvReader.h"

namespace hemiroll::game {

namespace {

namespace fs = std::filesystem;

std::string firstLine(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw AnalysisInputError(path.string() + ": cannot be read");
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

TrialData readRecording(const fs::path& path) {
  record::Recording r;
  try {
    r = record::RecordingReader::load(path, {.allowTruncatedTail = true});
  } catch (const record::RecordError& e) {
    throw AnalysisInputError(e.what());
  }
  TrialData trial;
  trial.source = path.string();
  trial.kind = "recording";
  if (r.truncatedTail) trial.notes.push_back("an interrupted recording: its cut last line is not used");
  if (!r.status.complete && !r.truncatedTail) trial.notes.push_back("the sidecar says the trial did not finish");
  namespace slot = physics::force_slot;
  for (const haptics::RecordRow& row : r.rows) {
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
  }
  if (trial.time.empty()) throw AnalysisInputError(path.string() + ": line 2: no rows after the header");
  return trial;
}

TrialData readFile(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw AnalysisInputError(path.string() + ": no such file or folder");
  const std::string header = firstLine(path);
  const std::string recordingHeader = record::CsvRowFormat::header();
  TrialData trial;
  if (header + "\n" == recordingHeader) {
    trial = readRecording(path);
  } else if (isSimCsvHeader(header)) {
    trial = readSimCsv(path);
  } else {
    throw AnalysisInputError(path.string() + ":1: neither a trial recording (time_s,tick,...) nor a `hemiroll sim` CSV "
                             "(t,x_p,y_p,...)");
  }
  trial.id = path.stem().string();
  return trial;
}

std::vector<fs::path> trialsIn(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file(ec) || entry.path().extension() != ".csv") continue;
    // The session's summary and an earlier analysis written into the folder are not trials.
    if (entry.path().filename() == "results.csv" || entry.path().filename() == "analysis.csv") continue;
    files.push_back(entry.path());
  }
  if (ec) throw AnalysisInputError(dir.string() + ": cannot be listed (" + ec.message() + ")");
  std::sort(files.begin(), files.end());
  if (files.empty()) throw AnalysisInputError(dir.string() + ": holds no trial CSV");
  return files;
}

}  // namespace

std::vector<TrialData> loadTrials(const std::vector<std::string>& paths) {
  std::vector<TrialData> trials;
  std::set<std::string> ids;
  for (const std::string& p : paths) {
    std::error_code ec;
    const std::vector<fs::path> files = fs::is_directory(p, ec) ? trialsIn(p) : std::vector<fs::path>{p};
    for (const fs::path& f : files) {
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
