// Fuzz target: a trial's CSV (engine/record/RecordingReader::loadCsv, which
// parses every row with CsvRowFormat), with and without a truncated tail.
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hemiroll::record;
  const auto file = hemiroll::fuzz::inputFile(data, size, ".csv");
  for (const bool tail : {false, true}) {
    try {
      bool truncated = false;
      RecordingReader::loadCsv(file, {.allowTruncatedTail = tail}, &truncated);
    } catch (const RecordError&) {
    }
  }
  return 0;
}
