// Fuzz target: a trial's sidecar JSON (engine/record/Sidecar).
#include "engine/record/RecordError.h"
#include "engine/record/Sidecar.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hemiroll::record;
  TrialMeta meta;
  SidecarStatus status;
  try {
    Sidecar::fromJson(std::string(hemiroll::fuzz::textOf(data, size)), "fuzz.json", meta, status);
  } catch (const RecordError&) {
  }
  return 0;
}
