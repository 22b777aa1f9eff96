#include "game/screens/LevelSelectScreen.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <tuple>

#include "engine/files/PrintableName.h"
#include "engine/script/LevelLoader.h"
#include "game/scores/ScoreStore.h"
#include "game/screens/FreePlay.h"
#include "game/screens/PlayScreen.h"
#include "game/screens/ScreenHost.h"
#include "game/screens/ScreenLayout.h"
#include "game/screens/ScreenStack.h"
#include "game/screens/TrialEnding.h"

namespace hemiroll::game {

std::vector<LevelEntry> scanLevels(const std::string& dir, const ListingBudget& budget) {
  std::vector<LevelEntry> out;
  const ListingClock clock(budget);
  script::LevelLoadOptions options;
  options.limits = clock.limits();
  for (const std::filesystem::path& file : luaFilesIn(dir)) {
    LevelEntry e;
    e.path = file.string();
    e.name = files::printable(file.filename().native());
    if (clock.spent()) {
      e.pending = true;
      e.description = clock.notLoaded();
      out.push_back(std::move(e));
      continue;
    }
    try {
      const script::LoadedLevel level = script::LevelLoader(options).loadFile(e.path);
      e.name = level.def.name;
      e.description = level.def.description;
      e.difficulty = level.def.difficulty;
      e.scoring = level.def.scoring;
    } catch (const std::exception& error) {
      e.error = error.what();
    }
    out.push_back(std::move(e));
  }
  // A new player meets the tutorials first, in their order; then the rest
  // from the easiest; a broken file last (its error is still shown).
  const auto rank = [](const LevelEntry& e) {
    const bool tutorial = std::filesystem::path(e.path).filename().string().rfind("tutorial", 0) == 0;
    return std::tuple(!e.error.empty(), e.pending, !tutorial, e.difficulty, e.path);
  };
  std::sort(out.begin(), out.end(), [&](const LevelEntry& a, const LevelEntry& b) { return rank(a) < rank(b); });
  return out;
}

int firstToPlay(const std::vector<LevelEntry>& entries) {
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (entries[i].error.empty() && !entries[i].pending && !entries[i].best.bestTime) return static_cast<int>(i);
  return 0;
}

void LevelSelectScreen::enter() {
  entries_ = scanLevels(host_.levelsDir());
  for (LevelEntry& e : entries_)
    if (e.error.empty() && !e.pending) e.best = host_.scores().best(e.name);
  if (!entered_) selected_ = firstToPlay(entries_);  // later visits keep the player's choice
  entered_ = true;
  selected_ = std::clamp(selected_, 0, std::max(0, static_cast<int>(entries_.size()) - 1));
}

void LevelSelectScreen::play(bool watch) {
  if (selected_ < 0 || selected_ >= static_cast<int>(entries_.size())) return;
  if (!entries_[static_cast<std::size_t>(selected_)].error.empty()) return;  // broken: its error is shown
  const std::string& path = entries_[static_cast<std::size_t>(selected_)].path;
  host_.screens().push(std::make_unique<PlayScreen>(host_, std::make_unique<FreePlay>(host_, path, watch)));
}

void LevelSelectScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown) return;
  const int n = static_cast<int>(entries_.size());
  if (e.key == platform::Key::Down && n > 0) selected_ = (selected_ + 1) % n;
  else if (e.key == platform::Key::Up && n > 0) selected_ = (selected_ + n - 1) % n;
  else if (e.key == platform::Key::Enter && !e.repeat) play();
  else if (e.code == 'a' && !e.repeat) play(/*watch=*/true);
  else if (e.key == platform::Key::Escape && !e.repeat) host_.screens().pop();
}

void LevelSelectScreen::paint() {
  beginCentredPanel("levels", 900);
  ImGui::SetWindowFontScale(1.6f);
  ImGui::Text("Choose a level");
  ImGui::SetWindowFontScale(1.0f);
  ImGui::TextDisabled("from %s", host_.levelsDir().c_str());
  if (entries_.empty()) ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "no levels (*.lua) found there");
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const LevelEntry& e = entries_[i];
    ImGui::PushID(static_cast<int>(i));
    const bool broken = !e.error.empty();
    std::string label = e.name;
    if (broken) label += "  (broken)";
    if (e.pending) label += "  (not loaded yet)";
    if (ImGui::Selectable(label.c_str(), selected_ == static_cast<int>(i), ImGuiSelectableFlags_AllowDoubleClick)) {
      selected_ = static_cast<int>(i);
      if (ImGui::IsMouseDoubleClicked(0)) play();
    }
    if (broken) {
      ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "    %s", e.error.c_str());
    } else if (e.pending) {
      ImGui::TextDisabled("    %s", e.description.c_str());
    } else {
      ImGui::SameLine(520);
      if (e.best.bestTime)
        ImGui::Text("best %.1f s  %s", *e.best.bestTime, e.best.bestMedal.c_str());
      else
        ImGui::TextDisabled("%s", e.best.attempts ? "not yet completed" : "not played");
    }
    ImGui::PopID();
  }
  if (selected_ < static_cast<int>(entries_.size()) && entries_[static_cast<std::size_t>(selected_)].error.empty()) {
    const LevelEntry& e = entries_[static_cast<std::size_t>(selected_)];
    ImGui::Separator();
    ImGui::TextWrapped("%s", e.description.c_str());
    if (const std::string medals = medalThresholds(e.scoring); !medals.empty())
      ImGui::TextDisabled("medals: %s", medals.c_str());
  }
  ImGui::Separator();
  if (ImGui::Button("Play  (Enter)")) play();
  ImGui::SameLine();
  if (ImGui::Button("Watch the autopilot  (A)")) play(/*watch=*/true);
  ImGui::SameLine();
  if (ImGui::Button("Back  (Esc)")) host_.screens().pop();
  ImGui::End();
}

}  // namespace hemiroll::game
