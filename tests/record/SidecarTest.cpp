#include "engine/record/Sidecar.h"

#include <gtest/gtest.h>

#include <bit>
#include <nlohmann/json.hpp>

#include "engine/record/RecordError.h"

namespace hemiroll::record {
namespace {

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

TrialMeta awkwardMeta() {
  TrialMeta m;
  m.trialId = "trial-007";
  m.participant = "p \"quoted\", with comma";
  m.session = "s2";
  m.levelName = "Über level";  // UTF-8 survives
  m.levelHash = "sha256:0123abcd";
  m.seed = 0xFFFF'FFFF'FFFF'FFFFull;  // the largest u64 survives JSON exactly
  m.params.radius = 0.1 + 0.2;     // not a short decimal
  m.params.shellMass = 1.0 / 3.0;
  m.params.pointMass = 5e-324;     // subnormal
  m.coupling.method = physics::ForceMethod::M2;
  m.coupling.stiffness = 123.456789012345678;
  m.guidance.kind = haptics::GuidanceKind::ErrorAugmentation;
  m.guidance.stiffness = 40.0;
  m.guidance.damping = 0.1 + 0.2;
  m.guidance.scale = 1.0 / 11.0;  // a fade value of trial 11 of 12
  m.deviceName = "udp-bridge";
  m.deviceSpec.maxForce = 3.3;
  m.recordEvery = 1;
  m.softwareVersion = "9.9.9";
  m.extra = {{"condition", "visual-only"}, {"block", "3"}};
  return m;
}

TEST(SidecarTest, MetadataRoundTripsExactly) {
  const TrialMeta m = awkwardMeta();
  SidecarStatus s;
  s.complete = true;
  s.startTime = "2026-11-22T06:40:00.123Z";
  s.rows = 42;
  TrialEnd end;
  end.outcome = "failure";
  end.reason = "tipped over";
  end.hasTiming = true;
  end.timing.latenessP999 = 4.2e-5;
  end.timing.missedTicks = 2;
  end.device = {{"stop", "the device reported a fault (status 1): check it"}, {"packets", "10 device states received"}};
  s.end = end;
  TrialMeta back;
  SidecarStatus sback;
  Sidecar::fromJson(Sidecar::toJson(m, s), "x.json", back, sback);
  EXPECT_EQ(back.participant, m.participant);
  EXPECT_EQ(back.levelName, m.levelName);
  EXPECT_EQ(back.seed, m.seed);
  EXPECT_EQ(bits(back.params.radius), bits(m.params.radius));
  EXPECT_EQ(bits(back.params.shellMass), bits(m.params.shellMass));
  EXPECT_EQ(bits(back.params.pointMass), bits(m.params.pointMass));
  EXPECT_EQ(bits(back.coupling.stiffness), bits(m.coupling.stiffness));
  EXPECT_EQ(back.coupling.method, physics::ForceMethod::M2);
  EXPECT_EQ(back.guidance.kind, haptics::GuidanceKind::ErrorAugmentation);
  EXPECT_EQ(bits(back.guidance.stiffness), bits(40.0));
  EXPECT_EQ(bits(back.guidance.damping), bits(0.1 + 0.2));
  EXPECT_EQ(bits(back.guidance.scale), bits(1.0 / 11.0));
  EXPECT_EQ(back.extra, m.extra);
  EXPECT_EQ(back.recordEvery, 1);
  ASSERT_TRUE(sback.end.has_value());
  EXPECT_EQ(sback.end->reason, "tipped over");
  EXPECT_EQ(bits(sback.end->timing.latenessP999), bits(4.2e-5));
  EXPECT_EQ(sback.end->timing.missedTicks, 2u);
  EXPECT_EQ(sback.end->device, end.device);  // outcome.device: a trial at a device's stop and packet counts
  EXPECT_TRUE(sback.complete);
  EXPECT_EQ(sback.rows, 42u);
}

// A trial without a device behind the bridge has no outcome.device.
TEST(SidecarTest, OnlyATrialAtADeviceHasOutcomeDevice) {
  SidecarStatus s;
  s.complete = true;
  s.end = TrialEnd{};
  const std::string json = Sidecar::toJson(awkwardMeta(), s);
  EXPECT_EQ(json.find("\"device\": {\n      \"stop\""), std::string::npos);
  TrialMeta back;
  SidecarStatus sback;
  Sidecar::fromJson(json, "x.json", back, sback);
  ASSERT_TRUE(sback.end.has_value());
  EXPECT_TRUE(sback.end->device.empty());
}

// No guidance has no spring: the sidecar says kind none with null numbers
// (it said none with 200 N/m and fade 1), and reads back as none.
TEST(SidecarTest, NoGuidanceWritesNoSpring) {
  SidecarStatus s;
  TrialMeta m = awkwardMeta();
  m.guidance = {};
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(Sidecar::toJson(m, s));
  EXPECT_EQ(j.at("guidance").at("kind"), "none");
  for (const char* key : {"stiffness_N_per_m", "damping_N_s_per_m", "max_error_m", "fade"})
    EXPECT_TRUE(j.at("guidance").at(key).is_null()) << key;
  TrialMeta back;
  Sidecar::fromJson(j.dump(), "none.json", back, s);
  EXPECT_EQ(back.guidance.kind, haptics::GuidanceKind::None);
  EXPECT_EQ(back.guidance.scale, 0.0);  // no guidance force, as results.csv's guidance_fade says
}

// A sidecar written before guidance has no "guidance" and reads as none;
// an unknown kind is a named error.
TEST(SidecarTest, GuidanceIsOptionalAndItsKindChecked) {
  SidecarStatus s;
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(Sidecar::toJson(awkwardMeta(), s));
  j.erase("guidance");
  TrialMeta back;
  Sidecar::fromJson(j.dump(), "old.json", back, s);
  EXPECT_EQ(back.guidance.kind, haptics::GuidanceKind::None);
  j["guidance"] = {{"kind", "pull"}, {"stiffness_N_per_m", 1.0}, {"damping_N_s_per_m", 0.0}, {"max_error_m", 0.02},
                   {"fade", 1.0}};
  try {
    Sidecar::fromJson(j.dump(), "bad.json", back, s);
    FAIL() << "an unknown guidance kind was read";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("guidance.kind: unknown kind 'pull'"), std::string::npos) << e.what();
  }
}

TEST(SidecarTest, StatesTheSamplingRateAndTheCodeNames) {
  TrialMeta m;
  m.tickPeriod = 0.001;
  m.recordEvery = 10;
  const auto j = nlohmann::json::parse(Sidecar::toJson(m, {}));
  EXPECT_DOUBLE_EQ(j["sampling"]["rate_Hz"].get<double>(), 100.0);
  EXPECT_EQ(j["codes"]["fault"][static_cast<int>(haptics::SafetyFault::LoopOverrun)],
            haptics::safetyFaultName(haptics::SafetyFault::LoopOverrun));
  EXPECT_EQ(j["complete"], false);
}

std::string errorOf(const std::string& text) {
  TrialMeta m;
  SidecarStatus s;
  try {
    Sidecar::fromJson(text, "trial.json", m, s);
  } catch (const RecordError& e) {
    return e.what();
  }
  return "";
}

// A level's or protocol's text is Lua bytes; JSON must be UTF-8. Invalid
// bytes become U+FFFD rather than an exception that would end the program.
TEST(SidecarTest, InvalidUtf8InTextIsReplacedNotThrown) {
  TrialMeta m = awkwardMeta();
  m.levelName = "bad \xff name";
  m.extra = {{"block_name", "\xc3("}};
  std::string text;
  ASSERT_NO_THROW(text = Sidecar::toJson(m, {}));
  TrialMeta back;
  SidecarStatus status;
  Sidecar::fromJson(text, "t.json", back, status);
  EXPECT_EQ(back.levelName, "bad \xef\xbf\xbd name");
  EXPECT_EQ(back.extra[0].second, "\xef\xbf\xbd(");
}

TEST(SidecarTest, BrokenSidecarsGiveNamedErrors) {
  const std::string good = Sidecar::toJson(TrialMeta{}, {});
  EXPECT_NE(errorOf(good.substr(0, good.size() / 2)).find("trial.json: "), std::string::npos);
  EXPECT_NE(errorOf(good.substr(0, good.size() / 2)).find("parse error"), std::string::npos);
  auto j = nlohmann::json::parse(good);
  j.erase("params");
  EXPECT_NE(errorOf(j.dump()).find("params"), std::string::npos) << errorOf(j.dump());
  j = nlohmann::json::parse(good);
  j["format_version"] = 99;
  EXPECT_NE(errorOf(j.dump()).find("format_version 99"), std::string::npos) << errorOf(j.dump());
  j = nlohmann::json::parse(good);
  j["coupling"]["method"] = "M9";
  EXPECT_NE(errorOf(j.dump()).find("M9"), std::string::npos) << errorOf(j.dump());
  j = nlohmann::json::parse(good);
  j["params"]["R_m"] = "big";
  EXPECT_NE(errorOf(j.dump()).find("trial.json"), std::string::npos);
  EXPECT_EQ(errorOf(good), "");
}

}  // namespace
}  // namespace hemiroll::record
