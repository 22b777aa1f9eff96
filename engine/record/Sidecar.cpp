#include "engine/record/Sidecar.h"

#include <nlohmann/json.hpp>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

using nlohmann::ordered_json;

namespace {

ordered_json codeNames(int count, const char* (*name)(int)) {
  ordered_json names = ordered_json::array();
  for (int i = 0; i < count; ++i) names.push_back(name(i));
  return names;
}

const char* eventName(int i) { return physics::domainEventName(static_cast<physics::DomainEvent>(i)); }
const char* engagementName(int i) { return haptics::engagementName(static_cast<haptics::Engagement>(i)); }
const char* faultName(int i) { return haptics::safetyFaultName(static_cast<haptics::SafetyFault>(i)); }

physics::ForceMethod methodFromName(const std::string& name) {
  if (const std::optional<physics::ForceMethod> m = physics::forceMethodFromName(name)) return *m;
  throw RecordError("unknown force method '" + name + "'");
}

ordered_json timingJson(const haptics::LoopTimingSummary& t) {
  return {{"lateness_p50_s", t.latenessP50}, {"lateness_p99_s", t.latenessP99},
          {"lateness_p999_s", t.latenessP999}, {"lateness_max_s", t.latenessMax},
          {"period_p50_s", t.periodP50},       {"period_max_s", t.periodMax},
          {"ticks", t.ticks},                  {"missed_ticks", t.missedTicks},
          {"wakeups", t.wakeups}};
}

haptics::LoopTimingSummary timingFrom(const ordered_json& j) {
  haptics::LoopTimingSummary t;
  t.latenessP50 = j.at("lateness_p50_s").get<double>();
  t.latenessP99 = j.at("lateness_p99_s").get<double>();
  t.latenessP999 = j.at("lateness_p999_s").get<double>();
  t.latenessMax = j.at("lateness_max_s").get<double>();
  t.periodP50 = j.at("period_p50_s").get<double>();
  t.periodMax = j.at("period_max_s").get<double>();
  t.ticks = j.at("ticks").get<std::uint64_t>();
  t.missedTicks = j.at("missed_ticks").get<std::uint64_t>();
  t.wakeups = j.at("wakeups").get<std::uint64_t>();
  return t;
}

}  // namespace

std::string Sidecar::toJson(const TrialMeta& m, const SidecarStatus& s) {
  ordered_json j;
  j["format"] = "hemiroll-trial";
  j["format_version"] = kSidecarFormatVersion;
  j["complete"] = s.complete;
  j["software"] = {{"name", "hemiroll"}, {"version", m.softwareVersion}};
  j["ids"] = {{"participant", m.participant}, {"session", m.session}, {"trial", m.trialId}};
  j["task"] = m.taskName;
  j["start_time"] = s.startTime;
  j["end_time"] = s.endTime;
  j["level"] = {{"name", m.levelName}, {"hash", m.levelHash}};
  j["seed"] = m.seed;
  j["params"] = {{"R_m", m.params.radius}, {"m_s_kg", m.params.shellMass},
                 {"m_p_kg", m.params.pointMass}, {"g_m_per_s2", m.params.gravity}};
  j["coupling"] = {{"method", physics::forceMethodName(m.coupling.method)},
                   {"stiffness_N_per_m", m.coupling.stiffness},
                   {"damping_N_s_per_m", m.coupling.damping},
                   {"alpha", m.coupling.alpha},
                   {"visual_only", m.coupling.visualOnly}};
  // No guidance has no spring: its numbers are null, not the defaults an
  // unused GuidanceDef carries (a reader took "none, 200 N/m" for a spring).
  if (m.guidance.kind != haptics::GuidanceKind::None)
    j["guidance"] = {{"kind", haptics::guidanceKindName(m.guidance.kind)},
                     {"stiffness_N_per_m", m.guidance.stiffness},
                     {"damping_N_s_per_m", m.guidance.damping},
                     {"max_error_m", m.guidance.maxError},
                     {"fade", m.guidance.scale}};
  else
    j["guidance"] = {{"kind", haptics::guidanceKindName(m.guidance.kind)},
                     {"stiffness_N_per_m", nullptr},
                     {"damping_N_s_per_m", nullptr},
                     {"max_error_m", nullptr},
                     {"fade", nullptr}};
  j["device"] = {{"name", m.deviceName},
                 {"max_force_N", m.deviceSpec.maxForce},
                 {"max_stiffness_N_per_m", m.deviceSpec.maxStiffness},
                 {"workspace_radius_m", m.deviceSpec.workspaceRadius},
                 {"has_force_output", m.deviceSpec.hasForceOutput}};
  j["sampling"] = {{"tick_period_s", m.tickPeriod}, {"record_every", m.recordEvery}, {"rate_Hz", m.samplingRate()}};
  j["columns"] = CsvRowFormat::columns();
  j["codes"] = {{"event", codeNames(kEventCodes, eventName)},
                {"engagement", codeNames(kEngagementCodes, engagementName)},
                {"fault", codeNames(kFaultCodes, faultName)}};
  ordered_json extra = ordered_json::object();
  for (const auto& [key, value] : m.extra) extra[key] = value;
  j["extra"] = extra;
  j["rows"] = s.rows;
  j["tick_gaps"] = s.tickGaps;
  if (s.end) {
    j["dropped_rows"] = s.end->droppedRows;
    j["outcome"] = {{"result", s.end->outcome}, {"reason", s.end->reason}};
    if (!s.end->device.empty()) {
      ordered_json device = ordered_json::object();
      for (const auto& [key, value] : s.end->device) device[key] = value;
      j["outcome"]["device"] = device;
    }
    j["timing"] = s.end->hasTiming ? timingJson(s.end->timing) : ordered_json(nullptr);
  } else {
    j["dropped_rows"] = nullptr;
    j["outcome"] = nullptr;
    j["timing"] = nullptr;
  }
  // Text from a level or protocol is bytes: invalid UTF-8 becomes U+FFFD
  // instead of an exception (JSON must be UTF-8).
  return j.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

void Sidecar::fromJson(const std::string& text, const std::string& source, TrialMeta& m, SidecarStatus& s) {
  try {
    const ordered_json j = ordered_json::parse(text);
    if (j.at("format").get<std::string>() != "hemiroll-trial") throw RecordError("not a hemiroll trial sidecar");
    const int version = j.at("format_version").get<int>();
    if (version != kSidecarFormatVersion)
      throw RecordError("format_version " + std::to_string(version) + ", this build reads " +
                        std::to_string(kSidecarFormatVersion));
    s.complete = j.at("complete").get<bool>();
    m.softwareVersion = j.at("software").at("version").get<std::string>();
    m.participant = j.at("ids").at("participant").get<std::string>();
    m.session = j.at("ids").at("session").get<std::string>();
    m.trialId = j.at("ids").at("trial").get<std::string>();
    m.taskName = j.at("task").get<std::string>();
    s.startTime = j.at("start_time").get<std::string>();
    s.endTime = j.at("end_time").get<std::string>();
    m.levelName = j.at("level").at("name").get<std::string>();
    m.levelHash = j.at("level").at("hash").get<std::string>();
    m.seed = j.at("seed").get<std::uint64_t>();
    const auto& p = j.at("params");
    m.params.radius = p.at("R_m").get<double>();
    m.params.shellMass = p.at("m_s_kg").get<double>();
    m.params.pointMass = p.at("m_p_kg").get<double>();
    m.params.gravity = p.at("g_m_per_s2").get<double>();
    const auto& c = j.at("coupling");
    m.coupling.method = methodFromName(c.at("method").get<std::string>());
    m.coupling.stiffness = c.at("stiffness_N_per_m").get<double>();
    m.coupling.damping = c.at("damping_N_s_per_m").get<double>();
    m.coupling.alpha = c.at("alpha").get<double>();
    m.coupling.visualOnly = c.at("visual_only").get<bool>();
    m.guidance = {};
    if (j.contains("guidance")) {  // absent from sidecars written before guidance: none
      const auto& g = j.at("guidance");
      if (!haptics::parseGuidanceKind(g.at("kind").get<std::string>(), m.guidance.kind))
        throw RecordError("guidance.kind: unknown kind '" + g.at("kind").get<std::string>() + "'");
      // null (no guidance) leaves the definition's defaults, and a fade of
      // 0: no guidance force acts, as results.csv's guidance_fade says.
      const auto number = [&g](const char* key, double& into, double ifNull) {
        into = g.at(key).is_null() ? ifNull : g.at(key).get<double>();
      };
      const haptics::GuidanceDef defaults;
      number("stiffness_N_per_m", m.guidance.stiffness, defaults.stiffness);
      number("damping_N_s_per_m", m.guidance.damping, defaults.damping);
      number("max_error_m", m.guidance.maxError, defaults.maxError);
      number("fade", m.guidance.scale, 0.0);
    }
    const auto& d = j.at("device");
    m.deviceName = d.at("name").get<std::string>();
    m.deviceSpec.maxForce = d.at("max_force_N").get<double>();
    m.deviceSpec.maxStiffness = d.at("max_stiffness_N_per_m").get<double>();
    m.deviceSpec.workspaceRadius = d.at("workspace_radius_m").get<double>();
    m.deviceSpec.hasForceOutput = d.at("has_force_output").get<bool>();
    m.tickPeriod = j.at("sampling").at("tick_period_s").get<double>();
    m.recordEvery = j.at("sampling").at("record_every").get<int>();
    if (!CsvRowFormat::knownColumns(j.at("columns").get<std::vector<std::string>>()))
      throw RecordError("its columns differ from this build's CSV columns");
    m.extra.clear();
    for (const auto& [key, value] : j.at("extra").items()) m.extra.emplace_back(key, value.get<std::string>());
    s.rows = j.at("rows").get<std::uint64_t>();
    s.tickGaps = j.at("tick_gaps").get<std::uint64_t>();
    s.end.reset();
    if (!j.at("outcome").is_null()) {
      TrialEnd end;
      end.outcome = j.at("outcome").at("result").get<std::string>();
      end.reason = j.at("outcome").at("reason").get<std::string>();
      if (const auto device = j.at("outcome").find("device"); device != j.at("outcome").end())
        for (const auto& [key, value] : device->items()) end.device.emplace_back(key, value.get<std::string>());
      end.droppedRows = j.at("dropped_rows").get<std::uint64_t>();
      end.hasTiming = !j.at("timing").is_null();
      if (end.hasTiming) end.timing = timingFrom(j.at("timing"));
      s.end = end;
    }
  } catch (const nlohmann::json::exception& e) {
    throw RecordError(source + ": " + e.what());
  } catch (const RecordError& e) {
    throw RecordError(source + ": " + e.what());
  }
}

}  // namespace hemiroll::record
