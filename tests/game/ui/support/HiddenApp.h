#pragma once
// The app as the window tests open it: hidden, no vsync and no frame pacing
// (frames as fast as llvmpipe draws them), and every file it keeps - scores,
// settings, replays, ghosts - inside `dir`, never the user's.

#include <cstdlib>
#include <filesystem>

#include "game/ui/app/App.h"

namespace hemiroll::test {

inline game::AppDef hiddenAppIn(const std::filesystem::path& dir) {
  setenv("HEMIROLL_DATA_DIR", dir.c_str(), 1);  // replays and ghosts
  game::AppDef def;
  def.hidden = true;
  def.vsync = false;
  def.paceFrames = false;
  def.scoresFile = (dir / "scores.sqlite").string();
  def.settingsFile = (dir / "settings.json").string();
  return def;
}

}  // namespace hemiroll::test
