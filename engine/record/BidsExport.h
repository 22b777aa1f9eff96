#pragma once
// BIDS-motion export of one recording (BIDS specification, "Motion"):
//   sub-<p>[_ses-<s>]_task-<t>_tracksys-<sys>[_run-<n>]_motion.tsv
//       the samples, tab-separated, no header, one row per CSV row;
//   ..._channels.tsv   name, component, type, tracked_point, units (header);
//   ..._motion.json    TaskName, SamplingFrequency, TrackingSystemName and
//                      the recommended channel counts and descriptions.
// BIDS labels are alphanumeric: other characters of the ids are dropped, and
// an id left empty is an error.

#include <filesystem>
#include <string>

#include "engine/record/RecordingReader.h"

namespace hemiroll::record {

struct BidsOptions {
  std::string trackingSystem = "hemiroll";
  // Run index; empty: the digits of the trial id (none: no run entity).
  std::string run;
};

struct BidsFiles {
  std::filesystem::path motionTsv, channelsTsv, motionJson;
};

class BidsExport {
 public:
  // Writes the three files into dir (created if needed). Throws RecordError.
  static BidsFiles write(const Recording& recording, const std::filesystem::path& dir, const BidsOptions& options = {});
  // The file name stem shared by the three files (without _motion.tsv etc.).
  static std::string stem(const Recording& recording, const BidsOptions& options = {});
};

}  // namespace hemiroll::record
