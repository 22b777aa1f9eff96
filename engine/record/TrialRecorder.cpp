#include "engine/record/TrialRecorder.h"

#include <ctime>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/FileNames.h"
#include "engine/record/RecordError.h"
#include "engine/record/Sidecar.h"
#include "engine/record/WriterThread.h"

namespace hemiroll::record {

using Clock = std::chrono::steady_clock;

struct TrialRecorder::Impl {
  Impl(const std::filesystem::path& dir, const TrialMeta& m, const RecorderOptions& o)
      : meta(m),
        options(o),
        csvPath(dir / (m.trialId + ".csv")),
        sidecarPath(dir / (m.trialId + ".json")),
        csv(csvPath, "wbx") {}

  void write(const haptics::RecordRow& row) {
    line.clear();
    CsvRowFormat::append(row, line);
    csv.write(line);
    if (rows > 0 && row.tick != lastTick + static_cast<std::uint64_t>(meta.recordEvery)) ++tickGaps;
    lastTick = row.tick;
    ++rows;
    dirty = true;
  }

  // Called after every push and every drain, rows or not, so rows that
  // arrived just before the loop paused still reach the disk in time.
  void maybeFlush() {
    if (dirty && Clock::now() - lastFlush >= std::chrono::duration<double>(options.flushInterval)) flushNow();
  }

  void flushNow() {
    csv.flush();
    lastFlush = Clock::now();
    dirty = false;
  }

  std::size_t drain(haptics::RecordRing& ring) {
    std::size_t n = 0;
    haptics::RecordRow row;
    while (ring.pop(row)) {
      write(row);
      ++n;
    }
    maybeFlush();
    return n;
  }

  void writeSidecar(const std::optional<TrialEnd>& end) {
    SidecarStatus s;
    s.complete = end.has_value();
    s.startTime = startTime;
    s.endTime = end ? utcTimestamp() : std::string();
    s.rows = rows;
    s.tickGaps = tickGaps;
    s.end = end;
    writeFileAtomically(sidecarPath, Sidecar::toJson(meta, s));
  }

  TrialMeta meta;
  RecorderOptions options;
  std::filesystem::path csvPath, sidecarPath;
  DurableFile csv;
  std::string startTime = utcTimestamp();
  std::string line;
  std::uint64_t rows = 0, tickGaps = 0, lastTick = 0;
  Clock::time_point lastFlush = Clock::now();
  bool dirty = false;  // rows written since the last flush
  bool finished = false;
  WriterThread writer;  // last: joined before the members it uses go
};

TrialRecorder::TrialRecorder(const std::filesystem::path& dir, const TrialMeta& meta, const RecorderOptions& options) {
  if (!isSafeFileName(meta.trialId))
    throw RecordError("trial id '" + meta.trialId + "' is not a safe file name (letters, digits, '-', '_', '.')");
  if (!(meta.tickPeriod > 0.0) || meta.recordEvery < 1)
    throw RecordError("trial '" + meta.trialId + "': tickPeriod must be positive and recordEvery at least 1");
  // Never over an earlier trial's files: the CSV is created exclusively, and
  // a sidecar without its CSV is refused too.
  const std::filesystem::path sidecar = dir / (meta.trialId + ".json");
  if (std::filesystem::exists(sidecar))
    throw RecordError(sidecar.string() + ": already exists (a recording is never overwritten)");
  TrialMeta m = meta;
  if (m.softwareVersion.empty()) m.softwareVersion = softwareVersion();
  impl_ = std::make_unique<Impl>(dir, m, options);
  impl_->csv.write(CsvRowFormat::header());
  impl_->flushNow();
  if (!impl_->csv.ok()) throw RecordError(impl_->csv.error());
  impl_->writeSidecar(std::nullopt);
}

TrialRecorder::~TrialRecorder() {
  if (!impl_ || impl_->finished) return;
  stopWriter();
  impl_->flushNow();  // the sidecar keeps "complete": false
}

TrialRecorder::TrialRecorder(TrialRecorder&&) noexcept = default;
TrialRecorder& TrialRecorder::operator=(TrialRecorder&& other) noexcept {
  if (this != &other) {
    if (impl_ && !impl_->finished) {
      stopWriter();
      impl_->flushNow();
    }
    impl_ = std::move(other.impl_);
  }
  return *this;
}

void TrialRecorder::push(const haptics::RecordRow& row) {
  impl_->write(row);
  impl_->maybeFlush();
}

std::size_t TrialRecorder::drain(haptics::RecordRing& ring) { return impl_->drain(ring); }

void TrialRecorder::startWriter(haptics::RecordRing& ring) {
  Impl* impl = impl_.get();
  impl->writer.start([impl, &ring] { impl->drain(ring); }, impl->options.pollInterval);
}

void TrialRecorder::stopWriter() { impl_->writer.stop(); }

void TrialRecorder::flush() { impl_->flushNow(); }

void TrialRecorder::finish(const TrialEnd& end) {
  if (impl_->finished) throw RecordError(impl_->csvPath.string() + ": the trial was already finished");
  stopWriter();
  impl_->csv.close();
  impl_->finished = true;
  if (!impl_->csv.ok()) throw RecordError(impl_->csv.error());
  impl_->writeSidecar(end);
}

std::uint64_t TrialRecorder::rows() const { return impl_->rows; }
std::uint64_t TrialRecorder::tickGaps() const { return impl_->tickGaps; }
const std::filesystem::path& TrialRecorder::csvPath() const { return impl_->csvPath; }
const std::filesystem::path& TrialRecorder::sidecarPath() const { return impl_->sidecarPath; }
const TrialMeta& TrialRecorder::meta() const { return impl_->meta; }
const std::string& TrialRecorder::startTime() const { return impl_->startTime; }

}  // namespace hemiroll::record
