#include "engine/record/CsvRowFormat.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <system_error>

namespace hemiroll::record {

using haptics::RecordRow;

static_assert(static_cast<int>(physics::DomainEvent::NonFinite) == kEventCodes - 1);
static_assert(static_cast<int>(haptics::Engagement::RampingOut) == kEngagementCodes - 1);
static_assert(static_cast<int>(haptics::SafetyFault::ForceSaturated) == kFaultCodes - 1);

namespace {

// Unit suffixes of the 12 slots (physics/StateLayout.h, eq. 22).
constexpr const char* kStateUnits[12] = {"m",        "m",        "m_per_s",  "m_per_s", "rad_per_s", "rad_per_s",
                                         "rad_per_s", "m",       "m",        "rad",     "rad",       "rad"};

std::vector<std::string> makeColumns() {
  std::vector<std::string> c = {"time_s", "tick"};
  for (int i = 0; i < 12; ++i) c.push_back(std::string(physics::kStateNames[i]) + "_" + kStateUnits[i]);
  const auto triple = [&c](const std::string& name, const std::string& unit) {
    for (const char* axis : {"x", "y", "z"}) c.push_back(name + "_" + axis + "_" + unit);
  };
  triple("proxy", "m");
  triple("proxy_v", "m_per_s");
  triple("Fh", "N");
  triple("f", "N");
  triple("Frendered", "N");
  for (const char* name : {"proxy_distance_m", "injected_energy_J", "ramp_scale", "lateness_s", "event",
                           "engagement", "fault", "paused", "force_clamped"})
    c.push_back(name);
  triple("Fguide", "N");  // added after the codes, so that a pre-guidance file is this one cut short
  return c;
}

std::string joined(const std::vector<std::string>& columns, std::size_t count) {
  std::string h;
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) h += ',';
    h += columns[i];
  }
  return h;
}

void appendInt(std::uint64_t value, std::string& out) {
  char buffer[24];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, r.ptr);
}

// The row's doubles in column order (after time and tick), as pointers so
// that writing and parsing walk the same list.
template <typename Row, typename Visit>
void forEachDouble(Row& row, Visit visit) {
  for (auto& v : row.state) visit(v);
  for (auto* t : {&row.proxyPosition, &row.proxyVelocity, &row.handForce, &row.modelForce, &row.renderedForce})
    for (auto& v : *t) visit(v);
  visit(row.proxyDistance);
  visit(row.injectedEnergy);
  visit(row.rampScale);
  visit(row.lateness);
}

bool parseUint(std::string_view text, std::uint64_t& value) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && !text.empty();
}

template <typename Enum>
bool parseCode(std::string_view text, Enum& value, std::uint64_t count) {
  std::uint64_t code = 0;
  if (!parseUint(text, code) || code >= count) return false;
  value = static_cast<Enum>(code);
  return true;
}

}  // namespace

const std::vector<std::string>& CsvRowFormat::columns() {
  static const std::vector<std::string> c = makeColumns();
  return c;
}

std::string CsvRowFormat::header() { return joined(columns(), columns().size()) + '\n'; }

std::string CsvRowFormat::headerBeforeGuidance() { return joined(columns(), kColumnsBeforeGuidance) + '\n'; }

bool CsvRowFormat::knownColumns(const std::vector<std::string>& names) {
  const std::vector<std::string>& c = columns();
  return names == c || (names.size() == kColumnsBeforeGuidance &&
                        std::equal(names.begin(), names.end(), c.begin()));
}

void appendDouble(double value, std::string& out) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);  // shortest round trip
  out.append(buffer, r.ptr);
}

std::string csvField(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string out = "\"";
  for (const char c : field) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csvLine(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) out += ',';
    out += csvField(fields[i]);
  }
  return out + "\n";
}

bool parseDouble(std::string_view text, double& value) {
  if (text.empty()) return false;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

void CsvRowFormat::append(const RecordRow& row, std::string& out) {
  appendDouble(row.time, out);
  out += ',';
  appendInt(row.tick, out);
  forEachDouble(row, [&out](double v) {
    out += ',';
    appendDouble(v, out);
  });
  for (const std::uint64_t code : {static_cast<std::uint64_t>(row.event), static_cast<std::uint64_t>(row.engagement),
                                   static_cast<std::uint64_t>(row.fault), static_cast<std::uint64_t>(row.paused),
                                   static_cast<std::uint64_t>(row.forceClamped)}) {
    out += ',';
    appendInt(code, out);
  }
  for (const double v : row.guidanceForce) {
    out += ',';
    appendDouble(v, out);
  }
  out += '\n';
}

std::string CsvRowFormat::parse(std::string_view line, RecordRow& row) {
  const std::vector<std::string>& names = columns();
  std::vector<std::string_view> fields;
  fields.reserve(names.size());
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  const bool beforeGuidance = fields.size() == kColumnsBeforeGuidance;
  if (fields.size() != names.size() && !beforeGuidance)
    return std::to_string(fields.size()) + " fields, expected " + std::to_string(names.size());
  std::size_t i = 0;
  const auto bad = [&](std::size_t k) {
    return "column " + std::to_string(k + 1) + " (" + names[k] + "): not a valid value '" + std::string(fields[k]) + "'";
  };
  if (!parseDouble(fields[i], row.time)) return bad(i);
  ++i;
  if (!parseUint(fields[i], row.tick)) return bad(i);
  ++i;
  std::string problem;
  forEachDouble(row, [&](double& v) {
    if (problem.empty() && !parseDouble(fields[i], v)) problem = bad(i);
    ++i;
  });
  if (!problem.empty()) return problem;
  if (!parseCode(fields[i], row.event, kEventCodes)) return bad(i);
  ++i;
  if (!parseCode(fields[i], row.engagement, kEngagementCodes)) return bad(i);
  ++i;
  if (!parseCode(fields[i], row.fault, kFaultCodes)) return bad(i);
  ++i;
  if (!parseCode(fields[i], row.paused, 2)) return bad(i);
  ++i;
  if (!parseCode(fields[i], row.forceClamped, 2)) return bad(i);
  ++i;
  row.guidanceForce = {};
  if (beforeGuidance) return {};
  for (double& v : row.guidanceForce) {
    if (!parseDouble(fields[i], v)) return bad(i);
    ++i;
  }
  return {};
}

}  // namespace hemiroll::record
