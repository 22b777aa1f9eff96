// Fuzz target: a level file's text (engine/script/LevelLoader).
#include "engine/script/LevelLoader.h"
#include "engine/script/ScriptError.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    hemiroll::script::LevelLoader().loadSource(hemiroll::fuzz::textOf(data, size), "fuzz.lua");
  } catch (const hemiroll::script::ScriptError&) {
  }
  return 0;
}
