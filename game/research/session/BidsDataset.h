#pragma once
// A BIDS dataset (BIDS 1.9, "Motion") from session folders: what `hemiroll
// bids` writes (issue 30).
//   DIR/dataset_description.json, README, participants.tsv, participants.json
//       (participant_id, group, block_order and the lab's participants-file
//       columns, from each session's manifest)
//   DIR/sub-<p>/[ses-<s>/]motion/<stem>_motion.tsv, _channels.tsv, _motion.json
//       (record::BidsExport, one set per trial)
//   DIR/sub-<p>/[ses-<s>/]motion/sub-<p>[_ses-<s>]_task-<t>_run-<n>_events.tsv
//       onset, duration, trial_type and the trial's place in the protocol
//       (group, block, condition, trial in block, guidance and its fade) and
//       its outcome, from the sidecar; then a stage_passed row per stage
//       passed, at its time in results.csv's stage_times_s.
// A trial that did not finish (no outcome in its sidecar, or a CSV cut
// short) is left out and named in `leftOut`, never exported as if whole.
// Knows the session folder's layout (PROTOCOLS.md); not the window.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace hemiroll::game {

struct BidsDatasetReport {
  int trials = 0;                    // exported
  std::vector<std::string> participants;  // BIDS labels, in order
  std::vector<std::string> leftOut;  // "<trial csv>: why"
};

// The session folders under `input`: itself when it holds session.json,
// else every folder one or two levels down that does (an experiment's
// participants and their sessions). Sorted.
std::vector<std::filesystem::path> sessionFolders(const std::filesystem::path& input);

// What the input rules out (an --out that is not empty, two trials that
// would get the same BIDS names): nothing has been written.
struct BidsInputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes the dataset for `sessions` into `out`, which must be new or empty.
// A trial that cannot be read or did not finish is left out and named.
// Throws BidsInputError (nothing written) or record::RecordError (a write
// failed), naming the file.
BidsDatasetReport writeBidsDataset(const std::vector<std::filesystem::path>& sessions,
                                   const std::filesystem::path& out, const std::string& datasetName);

}  // namespace hemiroll::game
