#include "game/research/session/BidsDataset.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <system_error>

#include "engine/record/BidsExport.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/ResultsFile.h"
#include "engine/record/TrialMeta.h"
#include "engine/files/FileKinds.h"
#include "game/research/session/SessionManifest.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

constexpr const char* kBidsVersion = "1.9.0";

// The trial's place in the protocol, as the session wrote it into the
// sidecar's `extra`, in the events file's column order.
constexpr const char* kProtocolColumns[] = {"group", "block", "block_name", "trial_in_block", "repetition",
                                            "condition", "condition_label"};

// What participants.tsv says of a participant, from their session manifest.
struct ParticipantFacts {
  std::string group;
  int blockOrder = 0;  // 0 = unknown (no manifest)
  record::Fields info;
};

// The stage times [s] results.csv gives each trial of a session ("" when
// it has none, or no results.csv).
std::map<std::string, std::string> stageTimesOf(const fs::path& session) {
  std::map<std::string, std::string> out;
  try {
    const record::ResultsTable table = record::ResultsFile(session / "results.csv").read();
    std::size_t trial = 0, times = table.columns.size();
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      if (table.columns[c] == "trial") trial = c;
      if (table.columns[c] == "stage_times_s") times = c;
    }
    if (times == table.columns.size()) return out;
    for (const auto& row : table.rows) out[row[trial]] = row[times];
  } catch (const std::exception&) {
    // Without a readable results.csv the events carry the trial alone.
  }
  return out;
}

std::string extraOf(const record::TrialMeta& meta, const std::string& key) {
  for (const auto& [k, v] : meta.extra)
    if (k == key) return v;
  return "n/a";
}

// A TSV cell: no tab or line break inside, "n/a" for nothing (BIDS).
std::string cell(std::string text) {
  if (text.empty()) return "n/a";
  for (char& ch : text)
    if (ch == '\t' || ch == '\n' || ch == '\r') ch = ' ';
  return text;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// sub-<p>, ses-<s> (or "") and the stem without the tracking system, from
// BidsExport's stem: the labels are BidsExport's, so the files agree.
struct Entities {
  std::string subject, session, eventsStem;
};

Entities entitiesOf(const std::string& stem) {
  Entities e;
  std::string rest = stem;
  std::vector<std::string> kept;
  while (!rest.empty()) {
    const std::size_t cut = rest.find('_');
    const std::string part = rest.substr(0, cut);
    rest = cut == std::string::npos ? "" : rest.substr(cut + 1);
    if (part.rfind("sub-", 0) == 0) e.subject = part;
    if (part.rfind("ses-", 0) == 0) e.session = part;
    if (part.rfind("tracksys-", 0) != 0) kept.push_back(part);
  }
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (i > 0) e.eventsStem += '_';
    e.eventsStem += kept[i];
  }
  return e;
}

std::string eventsTsv(const record::Recording& r, const std::string& stageTimes) {
  std::string out = "onset\tduration\ttrial_type";
  for (const char* c : kProtocolColumns) {
    out += '\t';
    out += c;
  }
  out += "\tlevel\tguidance\tguidance_fade\toutcome\treason\tstage\n";
  // From the first sample to the last, as the motion file's RecordingDuration.
  const double first = r.rows.empty() ? 0.0 : r.rows.front().time;
  const double duration = r.rows.empty() ? 0.0 : r.rows.back().time - first;
  const bool guided = r.meta.guidance.kind != haptics::GuidanceKind::None;
  std::vector<std::string> protocol;
  for (const char* c : kProtocolColumns) protocol.push_back(cell(extraOf(r.meta, c)));
  protocol.push_back(cell(r.meta.levelName));
  protocol.push_back(haptics::guidanceKindName(r.meta.guidance.kind));
  protocol.push_back(guided ? number(r.meta.guidance.scale) : std::string("n/a"));
  const auto line = [&](const std::string& onset, const std::string& length, const std::string& type,
                        const std::string& outcome, const std::string& reason, const std::string& stage) {
    out += onset + '\t' + length + '\t' + type;
    for (const std::string& c : protocol) out += '\t' + c;
    out += '\t' + outcome + '\t' + reason + '\t' + stage + '\n';
  };
  line("0", number(duration), "trial", cell(r.status.end->outcome), cell(r.status.end->reason), "n/a");
  // Each stage passed, when the judge passed it (results.csv's
  // stage_times_s, trial time), as an instant on the recording's clock.
  int stage = 0;
  for (std::size_t start = 0; start < stageTimes.size();) {
    std::size_t end = stageTimes.find(';', start);
    if (end == std::string::npos) end = stageTimes.size();
    const std::string text = stageTimes.substr(start, end - start);
    start = end + 1;
    ++stage;
    char* stop = nullptr;
    const double t = std::strtod(text.c_str(), &stop);
    if (text.empty() || stop != text.c_str() + text.size()) continue;
    line(number(std::max(0.0, t - first)), "0", "stage_passed", "n/a", "n/a", std::to_string(stage));
  }
  return out;
}

void writeTopFiles(const fs::path& out, const std::string& name, const std::vector<std::string>& participants,
                   const std::map<std::string, ParticipantFacts>& facts) {
  nlohmann::ordered_json d;
  d["Name"] = name;
  d["BIDSVersion"] = kBidsVersion;
  d["DatasetType"] = "raw";
  d["GeneratedBy"] = nlohmann::ordered_json::array(
      {{{"Name", "hemiroll"}, {"Version", record::softwareVersion()},
        {"Description", "hemiroll bids: session folders exported as BIDS motion"}}});
  record::writeFileAtomically(out / "dataset_description.json", d.dump(2) + "\n");
  // The lab's own columns (the participants file's), in the order first met.
  std::vector<std::string> labColumns;
  for (const auto& [subject, f] : facts)
    for (const auto& [key, value] : f.info)
      if (std::find(labColumns.begin(), labColumns.end(), key) == labColumns.end()) labColumns.push_back(key);
  std::string tsv = "participant_id\tgroup\tblock_order";
  for (const std::string& c : labColumns) tsv += '\t' + cell(c);
  tsv += '\n';
  for (const std::string& p : participants) {
    const auto found = facts.find(p);
    const ParticipantFacts none;
    const ParticipantFacts& f = found == facts.end() ? none : found->second;
    tsv += p + '\t' + cell(f.group) + '\t' + (f.blockOrder > 0 ? std::to_string(f.blockOrder) : "n/a");
    for (const std::string& c : labColumns) {
      std::string value;
      for (const auto& [key, v] : f.info)
        if (key == c) value = v;
      tsv += '\t' + cell(value);
    }
    tsv += '\n';
  }
  record::writeFileAtomically(out / "participants.tsv", tsv);
  nlohmann::ordered_json pj;
  pj["participant_id"] = {{"Description", "the participant id of the hemiroll session, letters and digits only"}};
  pj["group"] = {{"Description", "the protocol's group the participant was assigned to (session.json's group)"}};
  pj["block_order"] = {{"Description",
                        "the participant's block order: the row (1-based) of the protocol's balanced Latin square "
                        "over its counterbalanced blocks (1 when none are)"}};
  for (const std::string& c : labColumns)
    pj[c] = {{"Description", "from the lab's participants file (column '" + c + "'), as written there"}};
  record::writeFileAtomically(out / "participants.json", pj.dump(2) + "\n");
  record::writeFileAtomically(
      out / "README",
      "Movements of a hemisphere rolling without slipping on a plane, steered by a mass point on its face\n"
      "(hemiroll; Svinin et al. 2009). Written by `hemiroll bids` from session folders: one motion\n"
      "recording per trial (sampled state, proxy, forces; channels.tsv names them, in SI units), and\n"
      "an events file per trial with its place in the protocol and its outcome. Trials that did not\n"
      "finish are not in it.\n");
}

}  // namespace

std::vector<fs::path> sessionFolders(const fs::path& input) {
  std::vector<fs::path> found;
  std::error_code ec;
  if (fs::is_regular_file(input / "session.json", ec)) return {input};
  for (const auto& one : fs::directory_iterator(input, ec)) {
    if (!one.is_directory(ec)) continue;
    if (fs::is_regular_file(one.path() / "session.json", ec)) {
      found.push_back(one.path());
      continue;
    }
    for (const auto& two : fs::directory_iterator(one.path(), ec))
      if (two.is_directory(ec) && fs::is_regular_file(two.path() / "session.json", ec)) found.push_back(two.path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

namespace {

// A trial read and named, to be written once every trial is.
struct PlannedTrial {
  record::Recording recording;
  fs::path csv;
  std::string stem;
  Entities entities;
  ParticipantFacts facts;
  std::string stageTimes;
};

// The participant's group, block order and lab columns from the session's
// manifest; without a readable manifest the participant's row says n/a.
ParticipantFacts sessionFactsOf(const fs::path& session) {
  ParticipantFacts sessionFacts;
  try {
    const SessionManifest m = SessionManifest::fromJson(
        record::readWholeFile(session / "session.json", files::kSessionManifest), (session / "session.json").string());
    sessionFacts = {m.group, m.blockOrder, m.participantInfo};
  } catch (const std::exception&) {
    // Without a readable manifest the participant's row says n/a.
  }
  return sessionFacts;
}

// The session's trial files (samples), sorted; a sidecar whose samples are
// missing is left out, and said so in the report.
std::vector<fs::path> trialFilesOf(const fs::path& session, BidsDatasetReport& report) {
  std::error_code ec;
  std::vector<fs::path> trials;
  for (const auto& entry : fs::directory_iterator(session, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("trial-", 0) != 0) continue;
    if (entry.path().extension() == ".csv") {
      trials.push_back(entry.path());
    } else if (entry.path().extension() == ".json") {
      fs::path csv = entry.path();
      csv.replace_extension(".csv");
      if (!fs::exists(csv, ec)) report.leftOut.push_back(entry.path().string() + ": its samples (" +
                                                         csv.filename().string() + ") are missing");
    }
  }
  std::sort(trials.begin(), trials.end());
  return trials;
}

// Every finished trial of one session read and named into `planned`; one
// that would land on the files of another (`taken`: stem -> its trial) is
// refused, one that cannot be read or did not finish left out.
void planSession(const fs::path& session, BidsDatasetReport& report, std::vector<PlannedTrial>& planned,
                 std::map<std::string, fs::path>& taken) {
  const ParticipantFacts sessionFacts = sessionFactsOf(session);
  const std::map<std::string, std::string> stageTimes = stageTimesOf(session);
  for (const fs::path& csv : trialFilesOf(session, report)) {
    PlannedTrial p;
    p.csv = csv;
    try {
      p.recording = record::RecordingReader::load(csv);
      if (!p.recording.status.complete || !p.recording.status.end || p.recording.truncatedTail) {
        report.leftOut.push_back(csv.string() + ": the trial did not finish (no outcome in its sidecar)");
        continue;
      }
      p.stem = record::BidsExport::stem(p.recording);
    } catch (const std::exception& e) {
      report.leftOut.push_back(csv.string() + ": " + e.what());
      continue;
    }
    p.entities = entitiesOf(p.stem);
    p.facts = sessionFacts;
    if (const auto found = stageTimes.find(csv.stem().string()); found != stageTimes.end()) p.stageTimes = found->second;
    const auto [at, fresh] = taken.emplace(p.stem, csv);
    if (!fresh)
      throw BidsInputError(csv.string() + " and " + at->second.string() + " would both be " + p.stem +
                           " (BIDS labels keep letters and digits only): export them to separate datasets, or "
                           "give the participants or sessions ids that differ in letters or digits");
    planned.push_back(std::move(p));
  }
}

}  // namespace

BidsDatasetReport writeBidsDataset(const std::vector<fs::path>& sessions, const fs::path& out,
                                   const std::string& datasetName) {
  BidsDatasetReport report;
  std::error_code ec;
  // Into a new or empty folder only: files of an earlier export left beside
  // this one would be read as part of it (a subject participants.tsv omits).
  if (fs::exists(out, ec) && !fs::is_empty(out, ec))
    throw BidsInputError(out.string() + ": exists and is not empty; give a new folder for the dataset");
  // Every trial read and named first, so that two that would land on the
  // same files (ids that differ only in characters BIDS labels drop, the
  // same session given twice) are refused before anything is written.
  std::vector<PlannedTrial> planned;
  std::map<std::string, fs::path> taken;  // stem -> the trial it came from
  std::set<fs::path> seen;
  for (const fs::path& session : sessions) {
    const fs::path canonical = fs::weakly_canonical(session, ec);
    if (!seen.insert(ec ? session : canonical).second) continue;  // the same folder given twice
    planSession(session, report, planned, taken);
  }
  fs::create_directories(out, ec);
  if (ec) throw record::RecordError(out.string() + ": cannot create: " + ec.message());
  std::set<std::string> participants;
  std::map<std::string, ParticipantFacts> facts;
  for (const PlannedTrial& p : planned) {
    const fs::path dir = out / p.entities.subject / p.entities.session / "motion";
    record::BidsExport::write(p.recording, dir);
    record::writeFileAtomically(dir / (p.entities.eventsStem + "_events.tsv"), eventsTsv(p.recording, p.stageTimes));
    participants.insert(p.entities.subject);
    if (p.facts.blockOrder > 0) facts.emplace(p.entities.subject, p.facts);
    ++report.trials;
  }
  report.participants.assign(participants.begin(), participants.end());
  writeTopFiles(out, datasetName, report.participants, facts);
  return report;
}

}  // namespace hemiroll::game
