#include "game/screens/ResultsScreen.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <ctime>

#include "engine/platform/Window.h"
#include "engine/record/DataDirectory.h"
#include "engine/render/Renderer.h"
#include "engine/record/FileNames.h"
#include "game/app/Settings.h"
#include "game/scores/ScoreStore.h"
#include "game/screens/ScreenHost.h"
#include "game/screens/ScreenStack.h"
#include "game/trial/GhostFile.h"
#include "game/screens/PlayScreen.h"
#include "game/screens/ReplayScreen.h"
#include "game/screens/ScreenLayout.h"

namespace hemiroll::game {

ResultsScreen::ResultsScreen(ScreenHost& host, std::string levelPath, std::string levelName, TrialResult result,
                             std::filesystem::path replay, std::string replayNote, bool assisted, TrialEnding ending)
    : Screen(host),
      levelPath_(std::move(levelPath)),
      levelName_(std::move(levelName)),
      result_(std::move(result)),
      replay_(std::move(replay)),
      replayNote_(std::move(replayNote)),
      assisted_(assisted),
      ending_(std::move(ending)) {
  const std::string& player = host_.settings().participant;
  if (assisted_) {  // the autopilot's run is not the player's: no score, no best
    before_ = host_.scores().personalBest(levelName_, player);
    replayNote_ = "the autopilot played this run: it is not entered in your scores";
    return;
  }
  before_ = host_.scores().personalBest(levelName_, player);
  const bool success = result_.outcome == script::TrialOutcome::Success;
  newBest_ = success && (!before_.bestTime || result_.time < *before_.bestTime);
  ScoreEntry entry;
  entry.level = levelName_;
  entry.player = player;
  entry.success = success;
  entry.time = result_.time;
  entry.score = result_.score;
  entry.medal = script::medalName(result_.medal);
  stored_ = host_.scores().add(entry);
  if (newBest_ && !replay_.empty()) {
    const std::string error = keepAsGhost(replay_, ghostFile(record::dataDirectory(), levelName_, player), result_.time);
    replayNote_ = error.empty() ? "kept as your ghost: race it next time" : error;
  }
}

ResultsScreen::~ResultsScreen() {
  std::error_code ec;
  if (!replay_.empty() && !replaySaved_) std::filesystem::remove(replay_, ec);
}

void ResultsScreen::raceThisLine() {
  if (replay_.empty()) return;
  const std::string error =
      keepAsGhost(replay_, ghostFile(record::dataDirectory(), levelName_, host_.settings().participant), result_.time);
  replayNote_ = error.empty() ? "kept as your ghost: race the autopilot's line next time" : error;
}

void ResultsScreen::saveReplay() {
  if (replay_.empty() || replaySaved_) return;
  const std::string stem = record::fileStemOf(levelName_, "", "");
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  const std::filesystem::path target = replay_.parent_path() / (stem + "-" + stamp + ".hrr");
  std::error_code ec;
  std::filesystem::rename(replay_, target, ec);
  if (ec) {
    replayNote_ = "the replay could not be saved as " + target.string() + ": " + ec.message();
    return;
  }
  replay_ = target;
  replaySaved_ = true;
  replayNote_ = "replay saved: " + target.string();
}

void ResultsScreen::watchReplay() {
  if (!replay_.empty()) host_.screens().push(std::make_unique<ReplayScreen>(host_, levelPath_, replay_));
}

void ResultsScreen::again() { host_.screens().replace(std::make_unique<PlayScreen>(host_, levelPath_)); }

void ResultsScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown || e.repeat) return;
  if (e.key == platform::Key::Enter) again();
  else if (e.code == 's') saveReplay();
  else if (e.code == 'g' && assisted_ && result_.outcome == script::TrialOutcome::Success) raceThisLine();
  else if (e.code == 'w') watchReplay();
  else if (e.key == platform::Key::Escape) host_.screens().pop();
}

namespace {

const ImVec4 kGreenText(0.4f, 0.9f, 0.45f, 1), kRedText(1, 0.5f, 0.4f, 1), kGoldText(0.95f, 0.8f, 0.35f, 1);

ImVec4 medalColour(script::Medal m) {
  switch (m) {
    case script::Medal::Gold: return ImVec4(1.0f, 0.84f, 0.2f, 1);
    case script::Medal::Silver: return ImVec4(0.82f, 0.84f, 0.88f, 1);
    case script::Medal::Bronze: return ImVec4(0.85f, 0.55f, 0.3f, 1);
    case script::Medal::None: break;
  }
  return ImVec4(0.7f, 0.7f, 0.7f, 1);
}

// Confetti over the scene for the first seconds of a success: pieces fall
// from above the window on fixed pseudo-random paths (an index hash: the
// same picture every time, and nothing to allocate).
void drawConfetti(double seconds) {
  constexpr double kLasts = 3.0;  // [s]
  if (seconds > kLasts) return;
  const ImVec2 d = ImGui::GetIO().DisplaySize;
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  const ImU32 colours[] = {IM_COL32(255, 214, 51, 255), IM_COL32(90, 200, 255, 255), IM_COL32(110, 230, 120, 255),
                           IM_COL32(255, 120, 160, 255)};
  const auto alpha = static_cast<float>(1.0 - seconds / kLasts);
  for (unsigned i = 0; i < 90; ++i) {
    const unsigned h = (i * 2654435761u) ^ (i >> 3);
    const float x0 = static_cast<float>(h % 1000) / 1000.0f * d.x;
    const float speed = 0.35f + static_cast<float>((h >> 10) % 100) / 160.0f;  // screen heights per second
    const float y = (-0.1f + speed * static_cast<float>(seconds)) * d.y - static_cast<float>((h >> 17) % 200);
    const float x = x0 + 20.0f * std::sin(static_cast<float>(seconds) * 4.0f + static_cast<float>(i));
    ImU32 c = colours[i % 4];
    c = (c & 0x00FFFFFFu) | (static_cast<ImU32>(alpha * 255.0f) << 24);
    dl->AddRectFilled(ImVec2(x, y), ImVec2(x + 7, y + 4), c);
  }
}

}  // namespace

void ResultsScreen::paint() {
  // The trial's last frame stays in view, and the panel stands to its right.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  if (ending_.hasScene) {
    const platform::PixelSize px = host_.window().drawableSize();
    host_.renderer().render(ending_.scene, px.width, px.height);
  }
  const bool success = result_.outcome == script::TrialOutcome::Success;
  // Narrow enough to leave the hemisphere (the middle of the window) clear at 1280 px.
  const float width = std::min(ending_.hasScene ? 460.0f : 560.0f, display.x - 20.0f);
  if (ending_.hasScene) {
    ImGui::SetNextWindowPos(ImVec2(display.x - 10, display.y / 2), ImGuiCond_Always, ImVec2(1.0f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(width, 0), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("results", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  } else {
    beginCentredPanel("results", width);
  }
  ImGui::SetWindowFontScale(1.8f);
  if (success && result_.medal != script::Medal::None)
    ImGui::TextColored(medalColour(result_.medal), "Success: %s medal", script::medalName(result_.medal));
  else
    ImGui::TextColored(success ? kGreenText : kRedText, "%s", success ? "Success" : "Not this time");
  ImGui::SetWindowFontScale(1.0f);
  ImGui::TextWrapped("%s", levelName_.c_str());
  ImGui::Text("time %.2f s", result_.time);
  if (ending_.decidedBy.empty()) ImGui::TextWrapped("%s", result_.reason.c_str());
  ImGui::PushTextWrapPos(0.0f);
  for (const std::string& line : ending_.decidedBy) ImGui::TextDisabled("%s", line.c_str());
  ImGui::PopTextWrapPos();
  if (result_.score)
    ImGui::Text("score %.1f   medal %s", *result_.score, script::medalName(result_.medal));
  else if (!result_.scoreError.empty())
    ImGui::TextColored(kRedText, "no score: %s", result_.scoreError.c_str());
  if (const std::string medals = medalThresholds(ending_.scoring); !medals.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("medals: %s", medals.c_str());
    ImGui::PopTextWrapPos();
  }
  if (!result_.endCallbackError.empty())
    ImGui::TextColored(kRedText, "the level's end callback failed: %s", result_.endCallbackError.c_str());
  if (newBest_) ImGui::TextColored(kGoldText, "new personal best");
  if (before_.bestTime) ImGui::Text("personal best before: %.2f s", *before_.bestTime);
  if (!stored_ && !assisted_) ImGui::TextDisabled("(this trial could not be stored in %s)", host_.scores().file().c_str());
  const ImVec2 button(-1, 0);
  if (!replay_.empty()) {
    if (!replaySaved_ && ImGui::Button("Save replay  (S)", button)) saveReplay();
    if (ImGui::Button("Watch replay  (W)", button)) watchReplay();
  }
  if (assisted_ && result_.outcome == script::TrialOutcome::Success && !replay_.empty() &&
      ImGui::Button("Race this line  (G)", button))
    raceThisLine();
  // A saved file's path can be longer than the panel: wrapped, not clipped.
  if (!replayNote_.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", replayNote_.c_str());
    ImGui::PopTextWrapPos();
  }
  if (ImGui::Button("Play again  (Enter)", button)) again();
  if (ImGui::Button("Levels  (Esc)", button)) host_.screens().pop();
  const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  panelRect_ = WindowRect{"results", at.x, at.y, size.x, size.y};
  ImGui::End();
  if (success && !assisted_) drawConfetti(shownFor_);
}

}  // namespace hemiroll::game
