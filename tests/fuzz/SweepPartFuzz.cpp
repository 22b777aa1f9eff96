// Fuzz target: a sweep part's manifest (game/research/sweep/SweepManifest) and its
// CSV table (game/research/sweep/SweepTable): the two files `sweep merge` reads.
#include "game/research/sweep/SweepError.h"
#include "game/research/sweep/SweepManifest.h"
#include "game/research/sweep/SweepTable.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hemiroll::game;
  try {
    parseManifest(std::string(hemiroll::fuzz::textOf(data, size)), "fuzz.json");
  } catch (const SweepError&) {
  }
  try {
    readSweepRows(hemiroll::fuzz::inputFile(data, size, ".csv"));
  } catch (const SweepError&) {
  }
  return 0;
}
