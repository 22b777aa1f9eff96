#pragma once
// Listing a folder of Lua files on the window's thread (the level select,
// the research screen) loads each of them: untrusted files, any of which may
// run as long as its limits allow (a level's chunk: 10 s of wall clock). A
// listing must never hold the window that long: each file is loaded with
// half a second of wall clock for its chunk and calls, and the whole listing
// stops loading after a few seconds; the files it did not reach are listed,
// marked as not loaded, and load in full when chosen.

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/script/SandboxLimits.h"

namespace hemiroll::game {

struct ListingBudget {
  double perFileSeconds = 0.5;  // wall clock for one file's chunk and each call it makes
  double totalSeconds = 4.0;    // for the whole listing
};

// The *.lua files directly in `dir` (regular files; links followed), in
// name order, so that the tutorials are reached first when time runs out.
std::vector<std::filesystem::path> luaFilesIn(const std::string& dir);

class ListingClock {
 public:
  explicit ListingClock(const ListingBudget& budget = {});
  // The limits a file is loaded with while listing.
  const script::SandboxLimits& limits() const { return limits_; }
  // True once the listing's time is spent: later files are not loaded.
  bool spent() const;
  // What a file not loaded says.
  std::string notLoaded() const;

 private:
  ListingBudget budget_;
  script::SandboxLimits limits_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace hemiroll::game
