// Fuzz target: a replay log (engine/record/ReplayReader).
#include "engine/record/RecordError.h"
#include "engine/record/ReplayReader.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    hemiroll::record::ReplayReader::load(hemiroll::fuzz::inputFile(data, size, ".hrr"));
  } catch (const hemiroll::record::RecordError&) {
  }
  return 0;
}
