#include "game/research/sweep/SweepManifest.h"

#include <nlohmann/json.hpp>

#include "engine/record/ContentHash.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "game/research/sweep/SweepError.h"

namespace hemiroll::game {

namespace {

using json = nlohmann::ordered_json;
constexpr const char* kFormat = "hemiroll-sweep-1";

}  // namespace

std::string manifestJson(const SweepManifest& m) {
  const json j = {{"format", kFormat},
                  {"program", m.program},
                  {"spec_file", m.specFile},
                  {"description", m.description},
                  {"spec_hash", m.specHash},
                  {"spec", json::parse(m.specJson)},
                  {"points_total", m.pointsTotal},
                  {"shard", {{"index", m.shard.index}, {"count", m.shard.count}}},
                  {"points", {{"first", m.shard.index}, {"step", m.shard.count}, {"count", m.pointCount}}},
                  {"csv", m.csv},
                  {"complete", m.complete},
                  {"threads", m.threads},
                  {"wall_s", m.wallSeconds},
                  {"resumed_points", m.resumedPoints}};
  return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

SweepManifest parseManifest(const std::string& text, const std::filesystem::path& path) {
  SweepManifest m;
  try {
    const json j = json::parse(text);
    if (j.at("format").get<std::string>() != kFormat)
      throw std::invalid_argument("format '" + j.at("format").get<std::string>() + "', expected " + kFormat);
    m.program = j.at("program").get<std::string>();
    m.specFile = j.at("spec_file").get<std::string>();
    m.description = j.at("description").get<std::string>();
    m.specHash = j.at("spec_hash").get<std::string>();
    m.specJson = j.at("spec").dump();
    m.pointsTotal = j.at("points_total").get<long long>();
    m.shard = {j.at("shard").at("index").get<long long>(), j.at("shard").at("count").get<long long>()};
    const json& points = j.at("points");
    m.pointCount = points.at("count").get<long long>();
    if (points.at("first").get<long long>() != m.shard.index || points.at("step").get<long long>() != m.shard.count ||
        m.shard.count < 1 || m.shard.index < 0 || m.shard.index >= m.shard.count ||
        m.pointCount != m.shard.size(m.pointsTotal))
      throw std::invalid_argument("its shard and points do not agree");
    m.csv = j.at("csv").get<std::string>();
    if (m.csv.empty() || m.csv.find('/') != std::string::npos) throw std::invalid_argument("a bad csv name");
    m.complete = j.at("complete").get<bool>();
    m.threads = j.at("threads").get<int>();
    m.wallSeconds = j.at("wall_s").get<double>();
    m.resumedPoints = j.at("resumed_points").get<long long>();
  } catch (const std::exception& e) {  // json's parse, type and missing-key errors, and the checks above
    throw SweepError(SweepError::Kind::BadInput, path.string() + ": not a sweep manifest (" + e.what() + ")");
  }
  if (record::contentHash(m.specJson) != m.specHash)
    throw SweepError(SweepError::Kind::BadInput,
                     path.string() + ": its spec does not match its spec_hash (was the file edited by hand?)");
  return m;
}

SweepManifest readManifest(const std::filesystem::path& path) {
  std::string text;
  try {
    text = record::readWholeFile(path, files::kSweepManifest);
  } catch (const record::RecordError& e) {
    throw SweepError(SweepError::Kind::Environment, e.what());
  }
  return parseManifest(text, path);
}

}  // namespace hemiroll::game
