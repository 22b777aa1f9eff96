#include "game/ui/screens/SessionTrialPlay.h"

#include <stdexcept>

#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "game/research/session/ResearchSession.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/trial/DeviceStopWords.h"
#include "game/trial/DeviceTrial.h"
#include "game/trial/TrialRecording.h"

namespace hemiroll::game {

SessionTrialPlay::SessionTrialPlay(ScreenHost& host, ResearchSession& session, std::function<void(const SessionTrialEnd&)> done)
    : host_(host), research_(session), levelPath_(session.nextTrial().levelFile), done_(std::move(done)) {}

SessionTrialPlay::~SessionTrialPlay() = default;

namespace {

// results.csv's device columns for a person's trial: the last safety stop
// in words and, behind the bridge, its packet counts (DeviceTrial.h).
record::Fields deviceColumns(const PlaySession& session) {
  const auto* bridge = dynamic_cast<const haptics::UdpBridgeDevice*>(&session.device());
  std::string stop;
  if (!session.stops().empty()) {
    BridgeFacts facts;
    facts.present = bridge != nullptr;
    if (bridge) {
      facts.deviceStatus = bridge->lastDeviceFault();
      facts.stale = facts.deviceStatus == 0;
    }
    stop = deviceStopWords(session.stops().back().fault, facts, stopLimitsOf(session.loopDef().safety));
  }
  if (!bridge) return deviceResultFields(session.deviceName(), stop, nullptr);
  const haptics::UdpBridgeCounters counters = bridge->counters();
  return deviceResultFields(session.deviceName(), stop, &counters);
}

}  // namespace

std::unique_ptr<PlaySession> SessionTrialPlay::begin(script::LoadedLevel& level, PlaySessionDef& def) {
  level = research_.loadNextLevel();
  const ManifestTrial& trial = research_.nextTrial();
  def.coupling = level.def.coupling;
  def.replayFile = research_.folder() / (trial.trialId + ".replay");
  def.levelHash = trial.levelHash;
  // The plan's haptic guidance: the autopilot plans beside the participant
  // and the device pulls towards its plan (felt on a device with force output).
  def.guidance = trial.guidance;
  // The study's device (its protocol's, or the session's --device-profile) holds a device behind the bridge.
  if (def.device == haptics::kUdpDevice && research_.deviceProfile()) useDeviceProfile(def, *research_.deviceProfile());
  const std::optional<haptics::DeviceSpec> spec = haptics::DeviceFactory().specOf(def.device, def.deviceOptions);
  if (!spec) throw std::runtime_error("unknown device '" + def.device + "'");
  auto session = std::make_unique<PlaySession>(level, def);
  // The trial's loop (the player's device's mapping, the coupling, the
  // guidance) and the device's spec go into the sidecar.
  recording_ = research_.recordNext(level.def, session->loopDef(), def.device, *spec);
  session->record(recording_->tap());
  return session;
}

std::string SessionTrialPlay::title(const task::LevelDef& level) const {
  return "trial " + std::to_string(research_.nextTrial().index) + " of " + std::to_string(research_.trialCount()) +
         ": " + level.name;
}

void SessionTrialPlay::finished(PlaySession& session, TrialResult result, const task::LevelDef& /*level*/,
                                TrialEnding /*ending*/) {
  SessionTrialEnd recorded;
  recorded.recorded = true;
  recorded.result = std::move(result);
  end(std::move(recorded), &session);
}

void SessionTrialPlay::leftWithoutTrial(const std::string& error) {
  SessionTrialEnd notRecorded;
  notRecorded.error = error;
  end(std::move(notRecorded), nullptr);
}

void SessionTrialPlay::end(SessionTrialEnd end, const PlaySession* session) {
  if (ended_) return;  // two Escapes in one frame: the stack changes once
  ended_ = true;
  if (end.recorded && session != nullptr) {
    try {
      research_.finishNext(*recording_, end.result, session->timing(), deviceColumns(*session));
    } catch (const std::exception& e) {
      end.recorded = false;
      end.error = e.what();
    }
  }
  recording_.reset();
  host_.screens().pop();  // applied after this frame: the play screen lives until then
  done_(end);
}

}  // namespace hemiroll::game
