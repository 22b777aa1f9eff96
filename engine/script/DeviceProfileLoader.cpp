#include "engine/script/DeviceProfileLoader.h"

#include <filesystem>

#include "engine/script/DataFileLoader.h"
#include "engine/script/LevelFieldChecks.h"
#include "engine/script/LuaTableReader.h"

namespace hemiroll::script {

namespace {

constexpr DataFileKind kProfileFile{"device profile", "device profile"};

// A figure every profile must give: a positive number in the key's unit.
double required(const LuaTableReader& top, const char* key, const char* unit) {
  const auto value = readPositive(top, key, unit);
  if (!value) top.fail(key, std::string("missing; the device's figure in ") + unit + " (a positive number)");
  return *value;
}

DeviceProfileDef readProfile(const LuaTableReader& top, const std::string& name) {
  rejectUnknownLevelKeys(top, {"model", "maker", "peak_force_N", "continuous_force_N", "max_stiffness_N_per_m",
                               "max_damping_N_s_per_m", "workspace_width_m", "workspace_depth_m",
                               "workspace_height_m", "update_rate_Hz", "position_resolution_m", "force_axes",
                               "sensed_axes", "max_force_rate_N_per_s", "above_continuous_limit_s",
                               "workspace_margin_m", "sources"});
  DeviceProfileDef p;
  p.source = top.source();
  p.name = name;
  const auto model = top.string("model");
  if (!model || model->empty()) top.fail("model", "missing; the device's name as a sentence says it (a string)");
  p.model = *model;
  p.maker = top.string("maker").value_or("");
  top.string("sources");  // a string when present: where each figure comes from
  p.peakForceN = required(top, "peak_force_N", "N");
  p.continuousForceN = required(top, "continuous_force_N", "N");
  if (p.continuousForceN > p.peakForceN)
    top.fail("continuous_force_N", "is above peak_force_N: a device holds at most its peak force");
  p.maxStiffnessNPerM = required(top, "max_stiffness_N_per_m", "N/m");
  p.maxDampingNsPerM = readPositive(top, "max_damping_N_s_per_m", "N s/m");
  p.workspaceWidthM = required(top, "workspace_width_m", "m");
  p.workspaceDepthM = required(top, "workspace_depth_m", "m");
  p.workspaceHeightM = required(top, "workspace_height_m", "m");
  p.updateRateHz = required(top, "update_rate_Hz", "Hz");
  p.positionResolutionM = readPositive(top, "position_resolution_m", "m").value_or(0.0);
  p.forceAxes = readInteger(top, "force_axes", 1, 6).value_or(3);
  p.sensedAxes = readInteger(top, "sensed_axes", 1, 7).value_or(3);
  p.maxForceRateNPerS = readPositive(top, "max_force_rate_N_per_s", "N/s").value_or(p.maxForceRateNPerS);
  p.aboveContinuousLimitS = readPositive(top, "above_continuous_limit_s", "s").value_or(p.aboveContinuousLimitS);
  p.workspaceMarginM = readPositive(top, "workspace_margin_m", "m").value_or(p.workspaceMarginM);
  return p;
}

std::string stemOf(const std::string& name) { return std::filesystem::path(name).stem().string(); }

}  // namespace

DeviceProfileDef DeviceProfileLoader::loadFile(const std::string& path) const {
  return DataFileLoader(kProfileFile, limits_).loadFile(
      path, [&](const DataTable& t) { return readProfile(t.top, stemOf(path)); });
}

DeviceProfileDef DeviceProfileLoader::loadSource(std::string_view source, const std::string& name) const {
  return DataFileLoader(kProfileFile, limits_).loadSource(
      source, name, [&](const DataTable& t) { return readProfile(t.top, stemOf(name)); });
}

}  // namespace hemiroll::script
