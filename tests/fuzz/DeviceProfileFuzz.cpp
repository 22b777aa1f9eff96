// Fuzz target: a device profile's text (engine/script/DeviceProfileLoader).
#include "engine/script/DeviceProfileLoader.h"
#include "engine/script/ScriptError.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    hemiroll::script::DeviceProfileLoader().loadSource(hemiroll::fuzz::textOf(data, size), "fuzz.lua");
  } catch (const hemiroll::script::ScriptError&) {
  }
  return 0;
}
