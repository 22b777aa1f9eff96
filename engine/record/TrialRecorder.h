#pragma once
// Writes one trial: <dir>/<trialId>.csv (one row per RecordRow, the columns
// of CsvRowFormat) and <dir>/<trialId>.json (the sidecar, Sidecar.h).
//
// The sidecar is written at once with "complete": false and rewritten
// atomically (temp file + fsync + rename) by finish() with "complete": true,
// the outcome, the row counts and the loop's timing. The CSV is flushed to
// the kernel and fdatasync'ed at least every flushInterval, so a killed
// process loses at most the rows of the last flushInterval (plus the ring's
// and the writer's poll delay), and never a finished trial.
//
// Rows arrive one of two ways, through one formatting path:
//   push(row)            the calling thread (headless runs, tests);
//   startWriter(ring)    a writer thread draining the servo loop's ring
//                        every pollInterval until finish() or stopWriter().
// Do not push() while a writer runs. Movable; not copyable.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "engine/haptics/RecordRow.h"
#include "engine/record/TrialMeta.h"

namespace hemiroll::record {

struct RecorderOptions {
  // fflush + fdatasync at least this often [s]; the crash-loss bound.
  double flushInterval = 0.5;
  // The writer thread wakes this often to drain the ring [s]; 4096 rows of
  // ring last 4 s at 1 kHz, so 5 ms is far from overflowing.
  double pollInterval = 0.005;
};

class TrialRecorder {
 public:
  // Creates the files (the directory must exist). Throws RecordError naming
  // the file when it cannot, when it exists already (a trial is never
  // overwritten), or when meta.trialId is not a safe file name.
  TrialRecorder(const std::filesystem::path& dir, const TrialMeta& meta, const RecorderOptions& options = {});
  // Without finish(): stops the writer, flushes, and leaves the sidecar
  // saying "complete": false (the trial did not end properly).
  ~TrialRecorder();
  TrialRecorder(TrialRecorder&&) noexcept;
  TrialRecorder& operator=(TrialRecorder&&) noexcept;

  void push(const haptics::RecordRow& row);
  // Pops and writes every row the ring holds now; returns how many.
  std::size_t drain(haptics::RecordRing& ring);
  void startWriter(haptics::RecordRing& ring);
  // Joins the writer and drains what is left.
  void stopWriter();
  void flush();
  // Stops the writer, writes the rest, flushes and closes the CSV, and
  // rewrites the sidecar complete. Throws RecordError if any write failed
  // (disk full, ...), naming the file. At most once.
  void finish(const TrialEnd& end);

  // Counts as the writer left them: read them on the writing thread, or once
  // the writer is stopped (finish(), stopWriter()).
  std::uint64_t rows() const;
  // Rows whose tick did not follow the previous row's tick by recordEvery.
  std::uint64_t tickGaps() const;
  const std::filesystem::path& csvPath() const;
  const std::filesystem::path& sidecarPath() const;
  const TrialMeta& meta() const;
  const std::string& startTime() const;  // ISO-8601 UTC

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hemiroll::record
