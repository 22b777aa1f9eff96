#pragma once
// The trial's JSON sidecar: the metadata (TrialMeta), the state of the file
// (complete, rows, gaps, drops) and, once finished, the outcome and the
// loop's timing. Keys and units: docs/RECORDING.md. nlohmann-json writes
// doubles in their shortest round-trip form, so the parameters read back
// with the same bits.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "engine/record/TrialMeta.h"

namespace hemiroll::record {

inline constexpr int kSidecarFormatVersion = 1;

struct SidecarStatus {
  bool complete = false;
  std::string startTime;   // ISO-8601 UTC
  std::string endTime;     // empty until finished
  std::uint64_t rows = 0;
  std::uint64_t tickGaps = 0;
  std::optional<TrialEnd> end;  // set once finished
};

class Sidecar {
 public:
  static std::string toJson(const TrialMeta& meta, const SidecarStatus& status);
  // Throws RecordError naming `source` (the file) and what is wrong.
  static void fromJson(const std::string& text, const std::string& source, TrialMeta& meta, SidecarStatus& status);
};

}  // namespace hemiroll::record
