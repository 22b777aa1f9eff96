#include "game/research/session/SessionManifest.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace hemiroll::game {

// Keys in the order written (the default json sorts them): easier to read.
using json = nlohmann::ordered_json;

namespace {

constexpr const char* kFormat = "hemiroll-session";
constexpr int kFormatVersion = 1;

json trialJson(const ManifestTrial& t) {
  json j = {{"trial", t.index},
            {"trial_id", t.trialId},
            {"block", t.block},
            {"block_name", t.blockName},
            {"trial_in_block", t.trialInBlock},
            {"repetition", t.repetition},
            {"condition", t.condition},
            {"condition_label", t.conditionLabel},
            {"level_file", t.levelFile},
            {"level_name", t.levelName},
            {"level_hash", t.levelHash},
            {"method", t.method},
            {"kr_N_per_m", t.stiffness},
            {"kv_N_s_per_m", t.damping},
            {"alpha", t.alpha},
            {"time_limit_s", t.timeLimit},
            {"seed", t.seed},
            {"guidance", {{"kind", haptics::guidanceKindName(t.guidance.kind)},
                          {"stiffness_N_per_m", t.guidance.stiffness},
                          {"damping_N_s_per_m", t.guidance.damping},
                          {"max_error_m", t.guidance.maxError},
                          {"fade", t.guidance.scale}}},
            {"break_before", nullptr}};
  if (t.breakBefore)
    j["break_before"] = {{"message", t.breakBefore->message},
                         {"min_duration_s", t.breakBefore->minDuration},
                         {"stop", t.breakBefore->stop}};
  return j;
}

ManifestTrial trialOf(const json& j) {
  ManifestTrial t;
  t.index = j.at("trial").get<int>();
  t.trialId = j.at("trial_id").get<std::string>();
  t.block = j.at("block").get<int>();
  t.blockName = j.at("block_name").get<std::string>();
  t.trialInBlock = j.at("trial_in_block").get<int>();
  t.repetition = j.at("repetition").get<int>();
  t.condition = j.at("condition").get<int>();
  t.conditionLabel = j.at("condition_label").get<std::string>();
  t.levelFile = j.at("level_file").get<std::string>();
  t.levelName = j.at("level_name").get<std::string>();
  t.levelHash = j.at("level_hash").get<std::string>();
  t.method = j.at("method").get<std::string>();
  t.stiffness = j.at("kr_N_per_m").get<double>();
  t.damping = j.at("kv_N_s_per_m").get<double>();
  t.alpha = j.at("alpha").get<double>();
  t.timeLimit = j.at("time_limit_s").get<double>();
  t.seed = j.at("seed").get<std::uint64_t>();
  if (j.contains("guidance")) {  // manifests written before guidance have none
    const json& g = j.at("guidance");
    if (!haptics::parseGuidanceKind(g.at("kind").get<std::string>(), t.guidance.kind))
      throw json::other_error::create(501, "guidance.kind: unknown kind", &g);
    t.guidance.stiffness = g.at("stiffness_N_per_m").get<double>();
    t.guidance.damping = g.at("damping_N_s_per_m").get<double>();
    t.guidance.maxError = g.at("max_error_m").get<double>();
    t.guidance.scale = g.at("fade").get<double>();
  }
  if (const json& b = j.at("break_before"); !b.is_null())
    t.breakBefore = ManifestBreak{b.at("message").get<std::string>(), b.at("min_duration_s").get<double>(),
                                  b.at("stop").get<bool>()};
  return t;
}

}  // namespace

std::string SessionManifest::toJson() const {
  json j;
  j["format"] = kFormat;
  j["format_version"] = kFormatVersion;
  j["experiment"] = experiment;
  j["description"] = description;
  j["protocol"] = {{"file", protocolFile}, {"hash", protocolHash}, {"version", protocolVersion}};
  j["participant"] = participant;
  j["session"] = session;
  j["group"] = group;
  j["block_order"] = blockOrder;
  j["assigned_by"] = assignedBy;
  j["participant_info"] = json::object();
  for (const auto& [key, value] : participantInfo) j["participant_info"][key] = value;
  j["seed"] = seed;
  j["start_time"] = startTime;
  j["software"] = {{"version", softwareVersion}};
  j["sittings"] = json::array();
  for (const ManifestSitting& s : sittings)
    j["sittings"].push_back({{"start_time", s.startTime},
                             {"software_version", s.softwareVersion},
                             {"first_trial", s.firstTrial},
                             {"player", s.player}});
  j["plan"] = json::array();
  for (const ManifestTrial& t : plan) j["plan"].push_back(trialJson(t));
  j["aborted"] = json::array();
  for (const ManifestAborted& a : aborted) {
    json moved = json::array();
    for (const auto& [from, to] : a.moved) moved.push_back({{"from", from}, {"to", to}});
    j["aborted"].push_back({{"trial_id", a.trialId}, {"time", a.time}, {"reason", a.reason}, {"moved", moved}});
  }
  // Protocol text is bytes: invalid UTF-8 becomes U+FFFD (JSON must be UTF-8).
  return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

SessionManifest SessionManifest::fromJson(const std::string& text, const std::string& source) {
  SessionManifest m;
  try {
    const json j = json::parse(text);
    if (j.at("format").get<std::string>() != kFormat) throw std::runtime_error("not a session manifest");
    if (j.at("format_version").get<int>() != kFormatVersion)
      throw std::runtime_error("format version " + j.at("format_version").dump() + " (this program reads " +
                               std::to_string(kFormatVersion) + ")");
    m.experiment = j.at("experiment").get<std::string>();
    m.description = j.at("description").get<std::string>();
    m.protocolFile = j.at("protocol").at("file").get<std::string>();
    m.protocolHash = j.at("protocol").at("hash").get<std::string>();
    m.protocolVersion = j.at("protocol").at("version").get<std::string>();
    m.participant = j.at("participant").get<std::string>();
    m.session = j.at("session").get<std::string>();
    if (j.contains("group")) {  // manifests written before groups have none
      m.group = j.at("group").get<std::string>();
      m.blockOrder = j.at("block_order").get<int>();
      m.assignedBy = j.at("assigned_by").get<std::string>();
      for (const auto& [key, value] : j.at("participant_info").items())
        m.participantInfo.emplace_back(key, value.get<std::string>());
    }
    m.seed = j.at("seed").get<std::uint64_t>();
    m.startTime = j.at("start_time").get<std::string>();
    m.softwareVersion = j.at("software").at("version").get<std::string>();
    for (const json& s : j.at("sittings"))
      m.sittings.push_back({s.at("start_time").get<std::string>(), s.at("software_version").get<std::string>(),
                            s.at("first_trial").get<int>(), s.at("player").get<std::string>()});
    for (const json& t : j.at("plan")) m.plan.push_back(trialOf(t));
    for (const json& a : j.at("aborted")) {
      ManifestAborted entry{a.at("trial_id").get<std::string>(), a.at("time").get<std::string>(),
                            a.at("reason").get<std::string>(), {}};
      for (const json& f : a.at("moved")) entry.moved.emplace_back(f.at("from").get<std::string>(), f.at("to").get<std::string>());
      m.aborted.push_back(std::move(entry));
    }
  } catch (const json::exception& e) {
    throw std::runtime_error(source + ": not a readable session manifest (" + e.what() + ")");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(source + ": " + e.what());
  }
  return m;
}

}  // namespace hemiroll::game
