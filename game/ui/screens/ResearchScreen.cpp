#include "game/ui/screens/ResearchScreen.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "engine/files/PrintableName.h"
#include "engine/script/ProtocolLoader.h"
#include "game/ui/settings/Settings.h"
#include "game/research/session/ResearchSession.h"
#include "game/research/session/SessionFolder.h"
#include "game/ui/scores/ScoreStore.h"
#include "game/ui/hud/WrappedText.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenLayout.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/ui/screens/SessionScreen.h"

namespace hemiroll::game {

namespace {

const ImVec4 kRed(1, 0.5f, 0.4f, 1);

template <std::size_t N>
void copyInto(std::array<char, N>& buffer, const std::string& text) {
  buffer.fill('\0');
  std::copy_n(text.begin(), std::min(text.size(), N - 1), buffer.begin());
}

}  // namespace

std::vector<ProtocolEntry> scanProtocols(const std::string& dir, const ListingBudget& budget) {
  std::vector<ProtocolEntry> out;
  const ListingClock clock(budget);
  script::ProtocolLoadOptions options;
  options.limits = clock.limits();
  for (const std::filesystem::path& file : luaFilesIn(dir)) {
    ProtocolEntry e;
    e.path = file.string();
    e.experiment = files::printable(file.filename().native());
    if (clock.spent()) {
      e.error = clock.notLoaded();
      out.push_back(std::move(e));
      continue;
    }
    try {
      const task::ProtocolDef def = script::ProtocolLoader(options).loadFile(e.path);
      e.experiment = def.experiment;
      e.description = def.description;
      for (const task::BlockDef& b : def.blocks) e.trials += static_cast<int>(b.conditions.size()) * b.repetitions;
    } catch (const std::exception& error) {
      e.error = error.what();
    }
    out.push_back(std::move(e));
  }
  std::sort(out.begin(), out.end(), [](const ProtocolEntry& a, const ProtocolEntry& b) { return a.path < b.path; });
  return out;
}

void ResearchScreen::enter() {
  copyInto(participant_, host_.settings().participant);
  copyInto(session_, host_.settings().sessionId);
  protocols_ = scanProtocols((std::filesystem::path(host_.levelsDir()) / "protocols").string());
  selected_ = std::clamp(selected_, 0, std::max(0, static_cast<int>(protocols_.size()) - 1));
  refresh();
}

// Levels are looked for beside the protocol, then in the game's levels folder.
SessionRequest ResearchScreen::requestFor(const std::string& protocol) const {
  SessionRequest request;
  request.protocolPath = protocol;
  request.levelsDir = host_.levelsDir();
  request.participant = host_.settings().participant;
  request.session = host_.settings().sessionId;
  // Opening it to show its state loads the protocol and its levels on the
  // window's thread: as a listing does, within half a second each.
  request.loadLimits = ListingClock().limits();
  return request;
}

void ResearchScreen::select(int index) {
  selected_ = index;
  refresh();
}

// Opening the session reads the protocol, its levels and the folder (a few
// milliseconds) and writes nothing; done only when something changed.
void ResearchScreen::refresh() {
  canStart_ = false;
  if (protocols_.empty()) {
    status_ = host_.levelsDir().empty() ? "no levels folder found: start hemiroll with --levels DIR"
                                        : "no protocols (*.lua) in " + host_.levelsDir() + "/protocols";
    return;
  }
  const ProtocolEntry& p = protocols_[static_cast<std::size_t>(selected_)];
  if (!p.error.empty()) {
    status_ = "this protocol cannot be run (its error is above)";
    return;
  }
  try {
    const SessionRequest request = requestFor(p.path);
    const ResearchSession s(request);
    canStart_ = !s.complete();
    if (!s.resumed()) status_ = "a new session of " + std::to_string(s.trialCount()) + " trials";
    else if (s.complete()) status_ = "this session is complete (" + std::to_string(s.trialCount()) + " trials)";
    else
      status_ = "resumes at trial " + std::to_string(s.done() + 1) + " of " + std::to_string(s.trialCount()) +
                (s.interrupted().empty() ? "" : " (an interrupted trial's files will be moved aside)");
    // Between-subjects designs: the group and block order this participant gets (or has).
    if (!s.manifest().group.empty() || s.protocol().orderCount() > 1)
      status_ += "; group " + (s.manifest().group.empty() ? std::string("(none)") : s.manifest().group) +
                 ", block order " + std::to_string(s.manifest().blockOrder) + " (" + s.manifest().assignedBy + ")";
    status_ += "; data: " + s.folder().string();
  } catch (const std::exception& e) {
    status_ = e.what();
  }
}

void ResearchScreen::start() {
  if (!canStart_) return;
  host_.screens().push(
      std::make_unique<SessionScreen>(host_, requestFor(protocols_[static_cast<std::size_t>(selected_)].path)));
}

void ResearchScreen::leave() { host_.saveSettings(); }

void ResearchScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown || e.repeat) return;
  const int n = static_cast<int>(protocols_.size());
  if (e.key == platform::Key::Down && n > 0) select((selected_ + 1) % n);
  else if (e.key == platform::Key::Up && n > 0) select((selected_ + n - 1) % n);
  else if (e.key == platform::Key::Enter) start();
  else if (e.key == platform::Key::Escape) host_.screens().pop();
}

void ResearchScreen::paint() {
  Settings& s = host_.settings();
  beginCentredPanel("research", 900);
  ImGui::SetWindowFontScale(1.6f);
  ImGui::Text("Research session");
  ImGui::SetWindowFontScale(1.0f);
  ImGui::TextDisabled("protocols from %s/protocols (docs/PROTOCOLS.md)", host_.levelsDir().c_str());
  for (std::size_t i = 0; i < protocols_.size(); ++i) {
    const ProtocolEntry& p = protocols_[i];
    ImGui::PushID(static_cast<int>(i));
    const std::string label =
        p.error.empty() ? p.experiment + "  (" + std::to_string(p.trials) + " trials)" : p.experiment + "  (broken)";
    if (ImGui::Selectable(label.c_str(), selected_ == static_cast<int>(i))) select(static_cast<int>(i));
    if (!p.error.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, kRed);
      wrappedText("    " + p.error);
      ImGui::PopStyleColor();
    }
    else if (selected_ == static_cast<int>(i) && !p.description.empty()) wrappedText("    " + p.description);
    ImGui::PopID();
  }
  ImGui::Separator();
  // Ids name folders: letters, digits, '-' and '_' only; what is typed is kept as it is.
  const bool participantEdited = ImGui::InputText("participant id", participant_.data(), participant_.size());
  const bool sessionEdited = ImGui::InputText("session id", session_.data(), session_.size());
  if (participantEdited || sessionEdited) {
    s.participant = participant_.data();
    s.sessionId = session_.data();
    refresh();
  }
  ImGui::TextDisabled("data root: %s", defaultSessionsRoot().string().c_str());
  ImGui::TextDisabled("(free play stores its scores under this participant id in %s)", host_.scores().file().c_str());
  ImGui::TextDisabled("(set HEMIROLL_DATA_DIR or XDG_DATA_HOME to change it)");
  wrappedText(status_);
  ImGui::BeginDisabled(!canStart_);
  if (ImGui::Button("Start  (Enter)", ImVec2(-1, 0))) start();
  ImGui::EndDisabled();
  if (ImGui::Button("Back  (Esc)", ImVec2(-1, 0))) host_.screens().pop();
  ImGui::End();
}

}  // namespace hemiroll::game
