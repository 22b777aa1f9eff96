// Fuzz target: a protocol's text (engine/script/ProtocolLoader), its levels
// looked for in the shipped levels folder.
#include "engine/script/ProtocolLoader.h"
#include "engine/script/ScriptError.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hemiroll::script::ProtocolLoadOptions options;
  options.levelsDir = HEMIROLL_SOURCE_DIR "/levels";
  try {
    hemiroll::script::ProtocolLoader(options).loadSource(hemiroll::fuzz::textOf(data, size), "fuzz.lua",
                                                         HEMIROLL_SOURCE_DIR "/levels/protocols");
  } catch (const hemiroll::script::ScriptError&) {
  }
  return 0;
}
