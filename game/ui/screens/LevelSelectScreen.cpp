#include "game/ui/screens/LevelSelectScreen.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "engine/files/PrintableName.h"
#include "engine/platform/KeyNames.h"
#include "engine/script/LevelLoader.h"
#include "game/ui/settings/Settings.h"
#include "game/ui/hud/WrappedText.h"
#include "game/ui/view/ShippedDirectories.h"
#include "game/ui/scores/ScoreStore.h"
#include "game/ui/screens/FreePlay.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenLayout.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/ui/screens/TrialEnding.h"

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
      script::LoadedLevel level = script::LevelLoader(options).loadFile(e.path);
      e.name = level.def.name;
      e.description = level.def.description;
      e.difficulty = level.def.difficulty;
      e.scoring = level.def.scoring;
      e.medalTimes = medalTimes(level);
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

std::string levelRecord(const LevelBest& best) {
  char line[96];
  if (best.bestTime)
    std::snprintf(line, sizeof line, "best %.1f s%s%s", *best.bestTime, best.bestMedal == "none" ? "" : ", ",
                  best.bestMedal == "none" ? "" : best.bestMedal.c_str());
  else if (best.attempts > 0)
    std::snprintf(line, sizeof line, "tried %d time%s, not won yet", best.attempts, best.attempts == 1 ? "" : "s");
  else
    std::snprintf(line, sizeof line, "not played");
  return line;
}

void LevelSelectScreen::enter() {
  entries_ = scanLevels(host_.levelsDir());
  for (LevelEntry& e : entries_)
    if (e.error.empty() && !e.pending) e.best = host_.scores().best(e.name);
  if (!entered_) selected_ = firstToPlay(entries_);  // later visits keep the player's choice
  entered_ = true;
  selected_ = std::clamp(selected_, 0, std::max(0, static_cast<int>(entries_.size()) - 1));
}

bool LevelSelectScreen::playable() const {
  return selected_ >= 0 && selected_ < static_cast<int>(entries_.size()) &&
         entries_[static_cast<std::size_t>(selected_)].error.empty();
}

std::vector<std::string> LevelSelectScreen::playlist() const {
  std::vector<std::string> out;
  for (const LevelEntry& e : entries_)
    if (e.error.empty()) out.push_back(e.path);
  return out;
}

void LevelSelectScreen::play(bool watch) {
  if (!playable()) return;  // none, or broken: its error is shown
  const std::string& path = entries_[static_cast<std::size_t>(selected_)].path;
  auto mode = std::make_unique<FreePlay>(host_, path, watch);
  mode->setPlaylist(playlist());
  host_.screens().push(std::make_unique<PlayScreen>(host_, std::move(mode)));
}

void LevelSelectScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown) return;
  static const std::int32_t kHome = platform::keyFromName("Home"), kEnd = platform::keyFromName("End"),
                            kPageUp = platform::keyFromName("PageUp"), kPageDown = platform::keyFromName("PageDown");
  constexpr int kPage = 5;  // rows a page key moves
  const int n = static_cast<int>(entries_.size());
  if (e.key == platform::Key::Down && n > 0) selected_ = (selected_ + 1) % n;
  else if (e.key == platform::Key::Up && n > 0) selected_ = (selected_ + n - 1) % n;
  else if (e.code == kHome && kHome != 0 && n > 0) selected_ = 0;
  else if (e.code == kEnd && kEnd != 0 && n > 0) selected_ = n - 1;
  else if (e.code == kPageUp && kPageUp != 0 && n > 0) selected_ = std::max(0, selected_ - kPage);
  else if (e.code == kPageDown && kPageDown != 0 && n > 0) selected_ = std::min(n - 1, selected_ + kPage);
  else if (e.key == platform::Key::Enter && !e.repeat) play();
  else if (e.code == 'a' && !e.repeat) play(/*watch=*/true);
  else if (e.key == platform::Key::Escape && !e.repeat) host_.screens().pop();
}

void LevelSelectScreen::paint() {
  beginCentredPanel("levels", 900);
  ImGui::SetWindowFontScale(1.6f);
  ImGui::Text("Choose a level");
  ImGui::SetWindowFontScale(1.0f);
  const ImVec4 red(1, 0.5f, 0.4f, 1);
  if (host_.levelsDir().empty()) {
    // Nothing to play: say where the game looked and how to point it elsewhere.
    std::string looked;
    for (const std::filesystem::path& c : levelsDirectoryCandidates())
      looked += (looked.empty() ? "" : ", ") + c.string();
    wrappedText(red, "No levels found: no *.lua in " + looked +
                         ". Start hemiroll with --levels DIR, or set HEMIROLL_LEVELS to a folder of levels.");
  } else {
    wrappedTextDisabled("from " + host_.levelsDir());
    if (entries_.empty()) wrappedText(red, "No levels (*.lua) found there.");
  }
  // The keyboard's row bright, the hovered one only faint: Enter plays the bright one.
  ImGui::PushStyleColor(ImGuiCol_Header, ImVec4(0.26f, 0.59f, 0.98f, 0.85f));
  ImGui::PushStyleColor(ImGuiCol_HeaderHovered, ImVec4(0.26f, 0.59f, 0.98f, 0.22f));
  ImGui::PushStyleColor(ImGuiCol_HeaderActive, ImVec4(0.26f, 0.59f, 0.98f, 0.6f));
  const float recordAt = ImGui::GetContentRegionAvail().x * 0.58f;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const LevelEntry& e = entries_[i];
    ImGui::PushID(static_cast<int>(i));
    const bool broken = !e.error.empty();
    const bool chosen = selected_ == static_cast<int>(i);
    std::string label = (chosen ? "> " : "  ") + e.name;
    if (broken) label += "  (broken)";
    if (e.pending) label += "  (not loaded yet)";
    if (ImGui::Selectable(label.c_str(), chosen, ImGuiSelectableFlags_AllowDoubleClick)) {
      selected_ = static_cast<int>(i);
      if (ImGui::IsMouseDoubleClicked(0)) play();
    }
    if (broken) {
      ImGui::Indent();
      wrappedText(red, e.error);
      ImGui::Unindent();
    } else if (e.pending) {
      ImGui::TextDisabled("    %s", e.description.c_str());
    } else {
      ImGui::SameLine(recordAt);
      const std::string record = levelRecord(e.best);
      if (e.best.bestTime) ImGui::TextUnformatted(record.c_str());
      else ImGui::TextDisabled("%s", record.c_str());
    }
    ImGui::PopID();
  }
  ImGui::PopStyleColor(3);
  if (playable()) {
    const LevelEntry& e = entries_[static_cast<std::size_t>(selected_)];
    ImGui::Separator();
    wrappedText(withKeyNames(e.description, host_.settings().keys));
    if (const std::string medals = medalLine(e.scoring, e.medalTimes); !medals.empty())
      wrappedTextDisabled("medals: " + medals);
  }
  ImGui::Separator();
  // Only buttons that can work: none to play without a playable level.
  if (playable()) {
    if (ImGui::Button("Play  (Enter)")) play();
    ImGui::SameLine();
    if (ImGui::Button("Watch the autopilot  (A)")) play(/*watch=*/true);
    ImGui::SameLine();
  }
  if (ImGui::Button("Back  (Esc)")) host_.screens().pop();
  ImGui::End();
}

}  // namespace hemiroll::game
