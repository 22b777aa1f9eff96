// Fuzz target: a sweep spec's text (engine/script/SweepLoader).
#include "engine/script/ScriptError.h"
#include "engine/script/SweepLoader.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    hemiroll::script::SweepLoader().loadSource(hemiroll::fuzz::textOf(data, size), "fuzz.lua");
  } catch (const hemiroll::script::ScriptError&) {
  }
  return 0;
}
