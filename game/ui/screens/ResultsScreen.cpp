#include "game/ui/screens/ResultsScreen.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <ctime>

#include "engine/platform/Window.h"
#include "engine/record/DataDirectory.h"
#include "engine/render/Renderer.h"
#include "engine/record/FileNames.h"
#include "game/ui/settings/Settings.h"
#include "game/ui/scores/ScoreStore.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/trial/GhostFile.h"
#include "game/ui/hud/WrappedText.h"
#include "game/ui/screens/FreePlay.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/ReplayScreen.h"
#include "game/ui/screens/ScreenLayout.h"

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
  const bool success = result_.outcome == task::TrialOutcome::Success;
  newBest_ = success && (!before_.bestTime || result_.time < *before_.bestTime);
  ScoreEntry entry;
  entry.level = levelName_;
  entry.player = player;
  entry.success = success;
  entry.time = result_.time;
  entry.score = result_.score;
  entry.medal = task::medalName(result_.medal);
  stored_ = host_.scores().add(entry);
  // A first success becomes the ghost; one already there (the player's
  // own, or the autopilot's line they chose) is replaced only when they say
  // so (K): a slower best of theirs replaced the autopilot's line unasked.
  std::error_code ec;
  const bool ghostExists = std::filesystem::exists(ghostFile(record::dataDirectory(), levelName_, player), ec);
  if (newBest_ && !replay_.empty() && !ghostExists) raceThisRun();
}

bool ResultsScreen::offersRaceThisRun() const {
  return !assisted_ && !ghostKept_ && !replay_.empty() && result_.outcome == task::TrialOutcome::Success;
}

void ResultsScreen::raceThisRun() {
  if (replay_.empty() || assisted_) return;
  const std::filesystem::path ghost = ghostFile(record::dataDirectory(), levelName_, host_.settings().participant);
  std::string error = keepAsGhost(replay_, ghost, result_.time);
  if (error.empty()) error = keepGhostOwner(ghost, GhostOwner::Player);
  ghostKept_ = error.empty();
  replayNote_ = error.empty() ? "kept as your ghost: race it next time" : error;
}

std::string ResultsScreen::nextLevel() const {
  for (std::size_t i = 0; i + 1 < playlist_.size(); ++i)
    if (playlist_[i] == levelPath_) return playlist_[i + 1];
  return "";
}

ResultsScreen::~ResultsScreen() {
  std::error_code ec;
  if (!replay_.empty() && !replaySaved_) std::filesystem::remove(replay_, ec);
}

void ResultsScreen::raceThisLine() {
  if (replay_.empty()) return;
  const std::filesystem::path ghost = ghostFile(record::dataDirectory(), levelName_, host_.settings().participant);
  std::string error = keepAsGhost(replay_, ghost, result_.time);
  if (error.empty()) error = keepGhostOwner(ghost, GhostOwner::Autopilot);
  ghostKept_ = error.empty();
  replayNote_ = error.empty() ? "kept as the level's ghost: race the autopilot's line next time" : error;
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

void ResultsScreen::again() {
  auto mode = std::make_unique<FreePlay>(host_, levelPath_);
  mode->setPlaylist(playlist_);
  host_.screens().replace(std::make_unique<PlayScreen>(host_, std::move(mode)));
}

void ResultsScreen::next() {
  const std::string level = nextLevel();
  if (level.empty()) return;
  auto mode = std::make_unique<FreePlay>(host_, level);
  mode->setPlaylist(playlist_);
  host_.screens().replace(std::make_unique<PlayScreen>(host_, std::move(mode)));
}

void ResultsScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown || e.repeat) return;
  if (e.key == platform::Key::Enter || e.code == 'r') again();
  else if (e.code == 'n') next();
  else if (e.code == 's') saveReplay();
  else if (e.code == 'g' && assisted_ && result_.outcome == task::TrialOutcome::Success) raceThisLine();
  else if (e.code == 'k' && offersRaceThisRun()) raceThisRun();
  else if (e.code == 'w') watchReplay();
  else if (e.key == platform::Key::Escape) host_.screens().pop();
}

namespace {

const ImVec4 kGreenText(0.4f, 0.9f, 0.45f, 1), kRedText(1, 0.5f, 0.4f, 1), kGoldText(0.95f, 0.8f, 0.35f, 1);

ImVec4 medalColour(task::Medal m) {
  switch (m) {
    case task::Medal::Gold: return ImVec4(1.0f, 0.84f, 0.2f, 1);
    case task::Medal::Silver: return ImVec4(0.82f, 0.84f, 0.88f, 1);
    case task::Medal::Bronze: return ImVec4(0.85f, 0.55f, 0.3f, 1);
    case task::Medal::None: break;
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
  // The trial's last frame stays in view, and the panel stands to its right,
  // clear of the hemisphere.
  if (ending_.hasScene) {
    const platform::PixelSize px = host_.window().drawableSize();
    host_.renderer().render(ending_.scene, px.width, px.height);
  }
  const bool success = result_.outcome == task::TrialOutcome::Success;
  if (ending_.hasScene) beginSidePanel("results", 480);
  else beginCentredPanel("results", 560);
  ImGui::SetWindowFontScale(1.8f);
  if (success && result_.medal != task::Medal::None)
    ImGui::TextColored(medalColour(result_.medal), "Success: %s medal", task::medalName(result_.medal));
  else
    ImGui::TextColored(success ? kGreenText : kRedText, "%s", success ? "Success" : "Not this time");
  ImGui::SetWindowFontScale(1.0f);
  wrappedText(levelName_);
  ImGui::Text("time %.2f s", result_.time);
  if (ending_.decidedBy.empty()) wrappedText(result_.reason);
  for (const std::string& line : ending_.decidedBy) wrappedTextDisabled(line);
  if (result_.score)
    ImGui::Text("score %.1f   medal %s", *result_.score, task::medalName(result_.medal));
  else if (!result_.scoreError.empty())
    wrappedText(kRedText, "no score: " + result_.scoreError);
  if (const std::string medals = medalLine(ending_.scoring, ending_.medalTimes); !medals.empty())
    wrappedTextDisabled("medals: " + medals);
  if (!result_.endCallbackError.empty())
    wrappedText(kRedText, "the level's end callback failed: " + result_.endCallbackError);
  if (newBest_) ImGui::TextColored(kGoldText, "new personal best");
  if (before_.bestTime) ImGui::Text("personal best before: %.2f s", *before_.bestTime);
  if (!stored_ && !assisted_) wrappedTextDisabled("(this trial could not be stored in " + host_.scores().file().string() + ")");
  const ImVec2 button(-1, 0);
  const std::string next = nextLevel();
  if (!next.empty() && ImGui::Button("Next level  (N)", button)) this->next();
  if (ImGui::Button("Play again  (Enter, R)", button)) again();
  if (!replay_.empty()) {
    if (!replaySaved_ && ImGui::Button("Save replay  (S)", button)) saveReplay();
    if (ImGui::Button("Watch replay  (W)", button)) watchReplay();
  }
  if (assisted_ && success && !replay_.empty() && !ghostKept_ && ImGui::Button("Race this line  (G)", button))
    raceThisLine();
  if (offersRaceThisRun() && ImGui::Button("Race this run next time  (K)", button)) raceThisRun();
  // A saved file's path can be longer than the panel: wrapped, not cut.
  if (!replayNote_.empty()) wrappedTextDisabled(replayNote_);
  if (ImGui::Button("Levels  (Esc)", button)) host_.screens().pop();
  const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  panelRect_ = WindowRect{"results", at.x, at.y, size.x, size.y};
  ImGui::End();
  if (success && !assisted_) drawConfetti(shownFor_);
}

}  // namespace hemiroll::game
