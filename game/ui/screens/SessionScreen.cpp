#include "game/ui/screens/SessionScreen.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "engine/haptics/devices/MouseDevice.h"
#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/hud/WrappedText.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenLayout.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/ui/screens/SessionTrialPlay.h"

namespace hemiroll::game {

namespace {

const ImVec4 kGold(0.95f, 0.8f, 0.35f, 1);
const ImVec4 kRed(1, 0.5f, 0.4f, 1);

}  // namespace

SessionScreen::SessionScreen(ScreenHost& host, SessionRequest request) : Screen(host), request_(std::move(request)) {}

SessionScreen::~SessionScreen() = default;

void SessionScreen::open() {
  opened_ = true;
  try {
    session_ = std::make_unique<ResearchSession>(request_);
    if (const std::string problem = session_->couplingProblem(haptics::MouseDeviceDef{}.spec); !problem.empty())
      throw SessionError(SessionError::Kind::BadInput, problem);
    session_->begin(haptics::kMouseDevice);
  } catch (const std::exception& e) {
    error_ = e.what();
    session_.reset();
    return;
  }
  armBreak();
}

// The break before the next trial starts counting when it is first shown. A
// break that ended an earlier sitting has had its time (a day, often).
void SessionScreen::armBreak() {
  const ManifestBreak* pause = session_->pendingBreak();
  const int next = session_->complete() ? 0 : session_->nextTrial().index;
  if (pause == nullptr || next == breakFor_) return;
  breakFor_ = next;
  breakLeft_ = pause->stop ? 0.0 : pause->minDuration;
}

void SessionScreen::enter() {
  if (!opened_) open();
}

SessionScreen::Stage SessionScreen::stage() const {
  if (!session_ || !error_.empty()) return Stage::Error;
  if (session_->complete()) return Stage::Complete;
  if (session_->stopsHere()) return Stage::Stopped;
  if (session_->pendingBreak() != nullptr && breakLeft_ > 0.0) return Stage::Break;
  return Stage::Ready;
}

void SessionScreen::startTrial() {
  if (stage() != Stage::Ready) return;
  host_.screens().push(
      std::make_unique<PlayScreen>(host_, std::make_unique<SessionTrialPlay>(host_, *session_, [this](const SessionTrialEnd& end) {
        trialEnded(end);
      })));
}

void SessionScreen::trialEnded(const SessionTrialEnd& end) {
  if (!end.recorded) {
    error_ = end.error;
    return;
  }
  const ManifestTrial& trial = session_->manifest().plan.at(static_cast<std::size_t>(session_->done() - 1));
  char line[512];
  std::snprintf(line, sizeof line, "%s: %s, %s, %.1f s", trial.trialId.c_str(),
                task::trialOutcomeName(end.result.outcome), end.result.reason.c_str(), end.result.time);
  log_.emplace_back(line);
  armBreak();
}

void SessionScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown || e.repeat) return;
  if (e.key == platform::Key::Enter) startTrial();
  else if (e.key == platform::Key::Escape) host_.screens().pop();
}

void SessionScreen::update(double dt) { breakLeft_ = std::max(0.0, breakLeft_ - dt); }

void SessionScreen::paintNext(Stage stage) {
  const ManifestTrial& t = session_->nextTrial();
  if (const ManifestBreak* pause = session_->pendingBreak()) {
    ImGui::Separator();
    ImGui::TextColored(kGold, "Break");
    wrappedText(pause->message);
    if (stage == Stage::Break) ImGui::Text("the next block starts in %.0f s", std::ceil(breakLeft_));
  }
  ImGui::Separator();
  ImGui::TextColored(kGold, "Next: trial %d of %d (%s)", t.index, session_->trialCount(), t.trialId.c_str());
  const std::string block = "block " + std::to_string(t.block);
  ImGui::Text("%s%s%s, trial %d; condition: %s", block.c_str(), t.blockName == block ? "" : ": ",
              t.blockName == block ? "" : t.blockName.c_str(), t.trialInBlock, t.conditionLabel.c_str());
  ImGui::Text("level: %s", t.levelName.c_str());
  char alpha[40] = "";  // alpha is M3's (and visual's, which drives with M3)
  if (t.method == "M3" || t.method == "visual") std::snprintf(alpha, sizeof alpha, ", alpha %g", t.alpha);
  ImGui::Text("force: %s, k_r %.0f N/m, k_v %.1f N s/m%s; time limit %.0f s", t.method.c_str(), t.stiffness, t.damping,
              alpha, t.timeLimit);
  if (t.trialInBlock == 1 && !session_->instructionsOf(t).empty())
    wrappedText(session_->instructionsOf(t));
  ImGui::Spacing();
  ImGui::BeginDisabled(stage != Stage::Ready);
  if (ImGui::Button("Start the trial  (Enter)", ImVec2(-1, 0))) startTrial();
  ImGui::EndDisabled();
}

void SessionScreen::paint() {
  beginCentredPanel("session", 860);
  ImGui::SetWindowFontScale(1.6f);
  ImGui::Text("Research session%s%s", session_ ? ": " : "",
              session_ ? session_->manifest().experiment.c_str() : "");
  ImGui::SetWindowFontScale(1.0f);
  ImGui::Text("participant %s, session %s", request_.participant.c_str(), request_.session.c_str());
  const Stage now = stage();
  if (session_) {
    ImGui::TextDisabled("data: %s", session_->folder().string().c_str());
    ImGui::Text("%d of %d trials done%s", session_->done(), session_->trialCount(),
                session_->keptFromEarlier() > 0 ? " (resumed)" : "");
    for (const auto& [trialId, reason] : session_->interrupted())
      ImGui::TextDisabled("%s was %s: its files were moved aside", trialId.c_str(), reason.c_str());
    for (const std::string& line : log_) ImGui::TextDisabled("%s", line.c_str());
  }
  if (now == Stage::Error) {
    ImGui::TextColored(kRed, "The session cannot go on:");
    wrappedText(error_);
  } else if (now == Stage::Complete) {
    ImGui::Separator();
    ImGui::TextColored(kGold, "Session complete. Thank you!");
  } else if (now == Stage::Stopped) {
    ImGui::Separator();
    ImGui::TextColored(kGold, "This sitting ends here");
    wrappedText(session_->pendingBreak()->message);
    ImGui::TextDisabled("Start the same session again to continue.");
  } else {
    paintNext(now);
  }
  if (ImGui::Button("Back  (Esc)", ImVec2(-1, 0))) host_.screens().pop();
  ImGui::End();
}

}  // namespace hemiroll::game
