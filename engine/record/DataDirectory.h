#pragma once
// Where hemiroll keeps what it writes for a user (scores, settings, ghosts,
// replays, research sessions): HEMIROLL_DATA_DIR, else
// $XDG_DATA_HOME/hemiroll, else ~/.local/share/hemiroll, else ./.hemiroll.

#include <filesystem>

namespace hemiroll::record {

std::filesystem::path dataDirectory();

}  // namespace hemiroll::record
