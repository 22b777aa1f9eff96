#include "game/ui/screens/ListingBudget.h"

#include <algorithm>
#include <cstdio>

namespace hemiroll::game {

std::vector<std::filesystem::path> luaFilesIn(const std::string& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& f : std::filesystem::directory_iterator(dir, ec))
    if (f.is_regular_file(ec) && f.path().extension() == ".lua") files.push_back(f.path());
  std::sort(files.begin(), files.end());
  return files;
}

ListingClock::ListingClock(const ListingBudget& budget) : budget_(budget), start_(std::chrono::steady_clock::now()) {
  limits_.chunkWallSeconds = budget.perFileSeconds;
  limits_.callWallSeconds = budget.perFileSeconds;
}

bool ListingClock::spent() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() >= budget_.totalSeconds;
}

std::string ListingClock::notLoaded() const {
  char text[160];
  std::snprintf(text, sizeof text,
                "not loaded: the list took its %g s before reaching this file (choose it to load it)",
                budget_.totalSeconds);
  return text;
}

}  // namespace hemiroll::game
