// engine/script/DeviceProfileLoader: device profiles into DeviceProfileDef,
// every shipped profile loads, and each mistake is one message naming the
// file and the key.

#include "engine/script/DeviceProfileLoader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "engine/script/ScriptError.h"
#include "tests/support/ErrorMessage.h"

namespace hemiroll::script {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kSource = HEMIROLL_SOURCE_DIR;

constexpr const char* kGood = R"(
return {
  model = "Test Device", maker = "Nobody", sources = "a test",
  peak_force_N = 4, continuous_force_N = 1, max_stiffness_N_per_m = 900, max_damping_N_s_per_m = 5,
  workspace_width_m = 0.2, workspace_depth_m = 0.1, workspace_height_m = 0.15,
  update_rate_Hz = 2000, position_resolution_m = 0.00005, force_axes = 3, sensed_axes = 6,
  max_force_rate_N_per_s = 150, above_continuous_limit_s = 4, workspace_margin_m = 0.005,
})";

DeviceProfileDef load(const std::string& source) { return DeviceProfileLoader().loadSource(source, "lab/dev.lua"); }
std::string errorOf(const std::string& source) { return test::messageOf<ScriptError>([&] { load(source); }); }

// kGood with `key = ...` replaced by `key = value`, or by `replacement`
// (a whole entry, or "" to leave the key out).
std::string replaced(const std::string& key, const std::string& replacement) {
  std::string s = kGood;
  const std::size_t at = s.find(" " + key + " = ") + 1;
  std::size_t end = s.find_first_of(",\n", at);
  if (replacement.empty() && s[end] == ',') ++end;  // the entry and its comma
  s.replace(at, end - at, replacement);
  return s;
}
std::string with(const std::string& key, const std::string& value) {
  return replaced(key, value.empty() ? "" : key + " = " + value);
}

TEST(DeviceProfileLoader, ReadsEveryKeyInSiUnits) {
  const DeviceProfileDef p = load(kGood);
  EXPECT_EQ(p.name, "dev");
  EXPECT_EQ(p.source, "lab/dev.lua");
  EXPECT_EQ(p.model, "Test Device");
  EXPECT_EQ(p.maker, "Nobody");
  EXPECT_EQ(p.peakForceN, 4.0);
  EXPECT_EQ(p.continuousForceN, 1.0);
  EXPECT_EQ(p.maxStiffnessNPerM, 900.0);
  EXPECT_EQ(p.maxDampingNsPerM, 5.0);
  EXPECT_EQ(p.workspaceWidthM, 0.2);
  EXPECT_EQ(p.workspaceDepthM, 0.1);
  EXPECT_EQ(p.workspaceHeightM, 0.15);
  EXPECT_EQ(p.updateRateHz, 2000.0);
  EXPECT_EQ(p.positionResolutionM, 0.00005);
  EXPECT_EQ(p.forceAxes, 3);
  EXPECT_EQ(p.sensedAxes, 6);
  EXPECT_EQ(p.maxForceRateNPerS, 150.0);
  EXPECT_EQ(p.aboveContinuousLimitS, 4.0);
  EXPECT_EQ(p.workspaceMarginM, 0.005);
}

TEST(DeviceProfileLoader, OptionalKeysTakeTheProjectsDefaults) {
  const DeviceProfileDef p = load(with("max_damping_N_s_per_m", ""));
  EXPECT_FALSE(p.maxDampingNsPerM.has_value());
  const DeviceProfileDef q = load(with("max_force_rate_N_per_s", ""));
  EXPECT_EQ(q.maxForceRateNPerS, DeviceProfileDef{}.maxForceRateNPerS);
}

TEST(DeviceProfileLoader, EveryShippedProfileLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/devices")) {
    if (entry.path().extension() != ".lua") continue;
    SCOPED_TRACE(entry.path().string());
    const DeviceProfileDef p = DeviceProfileLoader().loadFile(entry.path().string());
    EXPECT_EQ(p.name, entry.path().stem().string());
    EXPECT_LE(p.continuousForceN, p.peakForceN);
    EXPECT_FALSE(p.model.empty());
    ++count;
  }
  // touch, touch_x, omega3, omega6, falcon, inverse3, generic
  EXPECT_EQ(count, 7);
}

TEST(DeviceProfileLoader, AMissingFigureNamesTheFileAndTheKey) {
  const std::string e = errorOf(with("peak_force_N", ""));
  EXPECT_THAT(e, StartsWith("lab/dev.lua:"));
  EXPECT_THAT(e, HasSubstr("peak_force_N: missing"));
}

TEST(DeviceProfileLoader, AnUnknownKeyIsNamedWithTheNearestAllowed) {
  const std::string e = errorOf(replaced("peak_force_N", "peak_force_n = 4"));
  EXPECT_THAT(e, StartsWith("lab/dev.lua:"));
  EXPECT_THAT(e, HasSubstr("peak_force_n"));
  EXPECT_THAT(e, HasSubstr("peak_force_N"));
}

TEST(DeviceProfileLoader, AWrongTypeOrANonPositiveFigureIsNamed) {
  EXPECT_THAT(errorOf(with("max_stiffness_N_per_m", "'stiff'")), HasSubstr("max_stiffness_N_per_m"));
  EXPECT_THAT(errorOf(with("workspace_depth_m", "0")), HasSubstr("workspace_depth_m: must be a positive number"));
  EXPECT_THAT(errorOf(with("update_rate_Hz", "-1000")), HasSubstr("update_rate_Hz"));
  EXPECT_THAT(errorOf(with("force_axes", "2.5")), HasSubstr("force_axes"));
}

TEST(DeviceProfileLoader, AContinuousForceAboveThePeakIsRefused) {
  EXPECT_THAT(errorOf(with("continuous_force_N", "5")), HasSubstr("continuous_force_N: is above peak_force_N"));
}

TEST(DeviceProfileLoader, AProfileWithoutAModelOrNotATableIsRefused) {
  EXPECT_THAT(errorOf(with("model", "")), HasSubstr("model: missing"));
  EXPECT_THAT(errorOf("return 3"), HasSubstr("the device profile must return a table"));
}

TEST(DeviceProfileLoader, AMissingFileIsNamed) {
  const std::string e = test::messageOf<ScriptError>([] { DeviceProfileLoader().loadFile("no/such/profile.lua"); });
  EXPECT_THAT(e, HasSubstr("no/such/profile.lua"));
}

}  // namespace
}  // namespace hemiroll::script
