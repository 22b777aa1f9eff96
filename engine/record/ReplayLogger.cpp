#include "engine/record/ReplayLogger.h"

#include <vector>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/record/TrialMeta.h"
#include "engine/record/WriterThread.h"

namespace hemiroll::record {

struct ReplayLogger::Impl {
  Impl(const std::filesystem::path& p, const ReplayHeader& h, double poll)
      : path(p), header(h), pollInterval(poll), file(p, "wbx") {}

  void write(const haptics::TickInput& in) {
    if (header.tickCount == 0) header.firstTick = in.tick;
    else if (in.tick != header.firstTick + header.tickCount && problem.empty())
      problem = "tick " + std::to_string(in.tick) + " follows tick " +
                std::to_string(header.firstTick + header.tickCount - 1) + " (inputs were lost)";
    const ReplayRecordBytes bytes = encodeReplayRecord(in);
    header.checksum = fnv1a(bytes.data(), bytes.size(), header.checksum);
    file.write(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    ++header.tickCount;
  }

  void write(const haptics::AppliedCommand& c) { commands.push_back(encodeReplayCommand(c)); }

  std::size_t drain(haptics::InputRing& ring, haptics::CommandRing* commandRing) {
    // Commands first: one applied at tick k was pushed before tick k's input.
    haptics::AppliedCommand c;
    while (commandRing != nullptr && commandRing->pop(c)) write(c);
    std::size_t n = 0;
    haptics::TickInput in;
    while (ring.pop(in)) {
      write(in);
      ++n;
    }
    return n;
  }

  std::filesystem::path path;
  ReplayHeader header;
  double pollInterval;
  DurableFile file;
  std::vector<ReplayCommandBytes> commands;
  std::string problem;
  bool finished = false;
  WriterThread writer;  // last: joined first
};

ReplayLogger::ReplayLogger(const std::filesystem::path& path, const ReplayHeader& header, double pollInterval) {
  ReplayHeader h = header;
  h.formatVersion = kReplayFormatVersion;
  h.flags = 0;
  h.tickCount = 0;
  h.firstTick = 1;
  h.checksum = kFnvOffset;
  h.commandCount = 0;
  if (h.softwareVersion.empty()) h.softwareVersion = softwareVersion();
  if (h.softwareVersion.size() >= kReplaySoftwareVersionSize || h.levelHash.size() >= kReplayLevelHashSize ||
      h.deviceKind.size() >= kReplayDeviceKindSize)
    throw RecordError(path.string() + ": software version, level hash or device kind too long for the replay header");
  impl_ = std::make_unique<Impl>(path, h, pollInterval);
  const ReplayHeaderBytes bytes = encodeReplayHeader(impl_->header);
  impl_->file.write(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  if (!impl_->file.ok()) throw RecordError(impl_->file.error());
}

ReplayLogger::~ReplayLogger() {
  if (impl_ && !impl_->finished) stopWriter();
}

ReplayLogger::ReplayLogger(ReplayLogger&&) noexcept = default;
ReplayLogger& ReplayLogger::operator=(ReplayLogger&& other) noexcept {
  if (this != &other) {
    if (impl_ && !impl_->finished) stopWriter();
    impl_ = std::move(other.impl_);
  }
  return *this;
}

void ReplayLogger::push(const haptics::TickInput& in) { impl_->write(in); }
void ReplayLogger::push(const haptics::AppliedCommand& command) { impl_->write(command); }

std::size_t ReplayLogger::drain(haptics::InputRing& inputs, haptics::CommandRing* commands) {
  return impl_->drain(inputs, commands);
}

void ReplayLogger::startWriter(haptics::InputRing& inputs, haptics::CommandRing* commands) {
  Impl* impl = impl_.get();
  impl->writer.start([impl, &inputs, commands] { impl->drain(inputs, commands); }, impl->pollInterval);
}

void ReplayLogger::stopWriter() { impl_->writer.stop(); }

void ReplayLogger::finish(std::uint64_t droppedInputs) {
  if (impl_->finished) throw RecordError(impl_->path.string() + ": the replay log was already finished");
  stopWriter();
  impl_->finished = true;
  if (droppedInputs > 0 && impl_->problem.empty())
    impl_->problem = std::to_string(droppedInputs) + " inputs were lost (the input ring overflowed)";
  // The complete flag only when every tick is there: a replay with a hole
  // cannot reproduce the run, and the reader refuses it.
  for (const ReplayCommandBytes& c : impl_->commands) {
    impl_->header.checksum = fnv1a(c.data(), c.size(), impl_->header.checksum);
    impl_->file.write(std::string_view(reinterpret_cast<const char*>(c.data()), c.size()));
  }
  impl_->header.commandCount = impl_->commands.size();
  if (impl_->problem.empty()) impl_->header.flags |= kReplayComplete;
  const ReplayHeaderBytes bytes = encodeReplayHeader(impl_->header);
  impl_->file.writeAt(0, bytes.data(), bytes.size());
  impl_->file.close();
  if (!impl_->file.ok()) throw RecordError(impl_->file.error());
  if (!impl_->problem.empty())
    throw RecordError(impl_->path.string() + ": the replay is unusable: " + impl_->problem);
}

std::uint64_t ReplayLogger::ticks() const { return impl_->header.tickCount; }
const std::filesystem::path& ReplayLogger::path() const { return impl_->path; }

}  // namespace hemiroll::record
