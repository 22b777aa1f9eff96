#include "engine/record/BidsExport.h"

#include <map>
#include <set>
#include <nlohmann/json.hpp>
#include <system_error>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/FileNames.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

namespace {

struct Channel {
  std::string name, component, type, trackedPoint, units;
};

// One channel per CSV column after tick, in CSV order (the tick counter is
// implied by the row index and left out). BIDS motion types (the
// specification's restricted list: ACCEL, ANGACCEL, GYRO, JNTANG, LATENCY,
// MAGN, MISC, ORNT, POS, VEL): angular velocity is GYRO.
std::vector<Channel> channels() {
  std::vector<Channel> c = {{"time", "n/a", "LATENCY", "n/a", "s"},
                            {"x_p", "x", "POS", "mass_point_in_face", "m"},
                            {"y_p", "y", "POS", "mass_point_in_face", "m"},
                            {"xd_p", "x", "VEL", "mass_point_in_face", "m/s"},
                            {"yd_p", "y", "VEL", "mass_point_in_face", "m/s"},
                            {"w_x", "x", "GYRO", "hemisphere", "rad/s"},
                            {"w_y", "y", "GYRO", "hemisphere", "rad/s"},
                            {"w_z", "z", "GYRO", "hemisphere", "rad/s"},
                            {"u_a", "x", "POS", "contact_on_plane", "m"},
                            {"v_a", "y", "POS", "contact_on_plane", "m"},
                            {"u_o", "n/a", "MISC", "contact_on_sphere", "rad"},
                            {"v_o", "n/a", "MISC", "contact_on_sphere", "rad"},
                            {"psi", "n/a", "MISC", "contact_on_sphere", "rad"}};
  const auto triple = [&c](const std::string& name, const std::string& type, const std::string& point,
                           const std::string& units) {
    for (const char* axis : {"x", "y", "z"}) c.push_back({name + "_" + axis, axis, type, point, units});
  };
  triple("proxy", "POS", "proxy", "m");
  triple("proxy_v", "VEL", "proxy", "m/s");
  triple("Fh", "MISC", "mass_point", "N");
  triple("f", "MISC", "mass_point", "N");
  triple("Frendered", "MISC", "device", "N");
  for (const auto& [name, units] : std::vector<std::pair<std::string, std::string>>{
           {"proxy_distance", "m"}, {"injected_energy", "J"}, {"ramp_scale", "n/a"}, {"lateness", "s"},
           {"event", "n/a"}, {"engagement", "n/a"}, {"fault", "n/a"}, {"paused", "n/a"}, {"force_clamped", "n/a"}})
    c.push_back({name, "n/a", "MISC", "n/a", units});
  triple("Fguide", "MISC", "proxy", "N");  // the CSV's order: after the codes
  return c;
}

std::string label(const std::string& id, const char* what) {
  std::string out;
  for (const char ch : id)
    if (isAsciiLetterOrDigit(ch)) out += ch;
  if (out.empty()) throw RecordError("BIDS export: the " + std::string(what) + " '" + id + "' has no letters or digits");
  return out;
}

std::string runOf(const Recording& r, const BidsOptions& o) {
  if (!o.run.empty()) return label(o.run, "run");
  std::string digits;
  for (const char ch : r.meta.trialId)
    if (ch >= '0' && ch <= '9') digits += ch;
  // BIDS run indices are non-negative integers; drop leading zeros but keep one digit.
  const std::size_t first = digits.find_first_not_of('0');
  return digits.empty() ? std::string() : first == std::string::npos ? "0" : digits.substr(first);
}

}  // namespace

std::string BidsExport::stem(const Recording& r, const BidsOptions& o) {
  std::string s = "sub-" + label(r.meta.participant, "participant");
  if (!r.meta.session.empty()) s += "_ses-" + label(r.meta.session, "session");
  s += "_task-" + label(r.meta.taskName, "task name");
  s += "_tracksys-" + label(o.trackingSystem, "tracking system");
  const std::string run = runOf(r, o);
  if (!run.empty()) s += "_run-" + run;
  return s;
}

BidsFiles BidsExport::write(const Recording& r, const std::filesystem::path& dir, const BidsOptions& o) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw RecordError(dir.string() + ": cannot create: " + ec.message());
  const std::string base = stem(r, o);
  BidsFiles files{dir / (base + "_motion.tsv"), dir / (base + "_channels.tsv"), dir / (base + "_motion.json")};
  const std::vector<Channel> chans = channels();

  std::string tsv;
  for (const haptics::RecordRow& row : r.rows) {
    std::string line;
    CsvRowFormat::append(row, line);
    // Same text as the CSV (same bits), minus the tick column, tab-separated.
    const std::size_t firstComma = line.find(','), secondComma = line.find(',', firstComma + 1);
    line = line.substr(0, firstComma) + line.substr(secondComma);
    for (char& ch : line)
      if (ch == ',') ch = '\t';
    tsv += line;
  }
  writeFileAtomically(files.motionTsv, tsv);

  std::string channelsTsv = "name\tcomponent\ttype\ttracked_point\tunits\n";
  std::map<std::string, int> counts;
  for (const Channel& c : chans) {
    channelsTsv += c.name + "\t" + c.component + "\t" + c.type + "\t" + c.trackedPoint + "\t" + c.units + "\n";
    ++counts[c.type];
  }
  writeFileAtomically(files.channelsTsv, channelsTsv);

  nlohmann::ordered_json j;
  j["TaskName"] = r.meta.taskName;
  j["TaskDescription"] = "hemiroll: steer a hemisphere rolling without slipping by moving a mass point on its face; level " +
                         r.meta.levelName;
  j["SamplingFrequency"] = r.meta.samplingRate();
  j["TrackingSystemName"] = o.trackingSystem;
  j["Manufacturer"] = "hemiroll (simulation)";
  j["ManufacturersModelName"] = r.meta.deviceName;
  j["SoftwareVersions"] = r.meta.softwareVersion;
  j["RecordingType"] = "continuous";
  j["RecordingDuration"] = r.rows.empty() ? 0.0 : r.rows.back().time - r.rows.front().time;
  j["MotionChannelCount"] = chans.size();
  for (const auto& [type, n] : counts) j[type + "ChannelCount"] = n;
  std::set<std::string> points;  // the tracked points the channels name
  for (const Channel& c : chans)
    if (c.trackedPoint != "n/a") points.insert(c.trackedPoint);
  j["TrackedPointsCount"] = points.size();
  // Not a BIDS key (BIDS allows more): the trial's haptic guidance, so that
  // the Fguide channels can be read without the hemiroll sidecar.
  // No guidance has no spring: null numbers, as in the sidecar.
  const bool guided = r.meta.guidance.kind != haptics::GuidanceKind::None;
  const auto orNull = [guided](double v) { return guided ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); };
  j["HapticGuidance"] = {{"Kind", haptics::guidanceKindName(r.meta.guidance.kind)},
                         {"StiffnessNPerM", orNull(r.meta.guidance.stiffness)},
                         {"DampingNSPerM", orNull(r.meta.guidance.damping)},
                         {"MaxErrorM", orNull(r.meta.guidance.maxError)},
                         {"Fade", orNull(r.meta.guidance.scale)}};
  j["MissingValues"] = "n/a";
  j["SubjectArtefactDescription"] = "n/a";
  writeFileAtomically(files.motionJson, j.dump(2, ' ', false, decltype(j)::error_handler_t::replace) + "\n");
  return files;
}

}  // namespace hemiroll::record
