#include "game/screens/ResultsScreen.h"

#include <imgui.h>

#include <ctime>

#include "engine/record/DataDirectory.h"
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
                             std::filesystem::path replay, std::string replayNote, bool assisted)
    : Screen(host),
      levelPath_(std::move(levelPath)),
      levelName_(std::move(levelName)),
      result_(std::move(result)),
      replay_(std::move(replay)),
      replayNote_(std::move(replayNote)),
      assisted_(assisted) {
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
    const std::string error = keepAsGhost(replay_, ghostFile(record::dataDirectory(), levelName_, player));
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
      keepAsGhost(replay_, ghostFile(record::dataDirectory(), levelName_, host_.settings().participant));
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

void ResultsScreen::paint() {
  beginCentredPanel("results", 560);
  const bool success = result_.outcome == script::TrialOutcome::Success;
  ImGui::SetWindowFontScale(1.8f);
  ImGui::TextColored(success ? ImVec4(0.4f, 0.9f, 0.45f, 1) : ImVec4(1, 0.5f, 0.4f, 1), "%s",
                     success ? "Success" : "Not this time");
  ImGui::SetWindowFontScale(1.0f);
  ImGui::Text("%s: %s", levelName_.c_str(), result_.reason.c_str());
  ImGui::Text("time %.2f s", result_.time);
  if (result_.score)
    ImGui::Text("score %.1f   medal %s", *result_.score, script::medalName(result_.medal));
  else if (!result_.scoreError.empty())
    ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "no score: %s", result_.scoreError.c_str());
  if (!result_.endCallbackError.empty())
    ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "the level's end callback failed: %s", result_.endCallbackError.c_str());
  if (newBest_) ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "new personal best");
  if (before_.bestTime) ImGui::Text("personal best before: %.2f s", *before_.bestTime);
  if (!stored_) ImGui::TextDisabled("(this trial could not be stored in %s)", host_.scores().file().c_str());
  const ImVec2 button(-1, 0);
  if (!replay_.empty()) {
    if (!replaySaved_ && ImGui::Button("Save replay  (S)", button)) saveReplay();
    if (ImGui::Button("Watch replay  (W)", button)) watchReplay();
  }
  if (assisted_ && result_.outcome == script::TrialOutcome::Success && !replay_.empty() &&
      ImGui::Button("Race this line  (G)", button))
    raceThisLine();
  if (!replayNote_.empty()) ImGui::TextDisabled("%s", replayNote_.c_str());
  if (ImGui::Button("Play again  (Enter)", button)) again();
  if (ImGui::Button("Levels  (Esc)", button)) host_.screens().pop();
  ImGui::End();
}

}  // namespace hemiroll::game
