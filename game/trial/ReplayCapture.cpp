#include "game/trial/ReplayCapture.h"

#include <cstdio>
#include <fstream>
#include <iterator>

#include "engine/record/RecordError.h"
#include "engine/record/ReplayFormat.h"
#include "engine/record/ReplayLogger.h"

namespace hemiroll::game {

ReplayCapture::ReplayCapture(const std::filesystem::path& file, const std::string& levelHash, double dt,
                             const std::string& deviceKind)
    : file_(file),
      inputs_(std::make_unique<haptics::InputRing>()),
      commands_(std::make_unique<haptics::CommandRing>()) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  std::filesystem::remove(file, ec);  // a leftover of a crashed session; the logger never overwrites
  record::ReplayHeader header;
  header.dt = dt;
  header.softwareVersion = "hemiroll play";
  header.levelHash = levelHash;
  header.deviceKind = deviceKind;
  logger_ = std::make_unique<record::ReplayLogger>(file, header);
}

ReplayCapture::~ReplayCapture() {
  if (started_ && !finished_) logger_->stopWriter();
}

void ReplayCapture::attach(haptics::ServoLoopDef& def) {
  def.inputRing = inputs_.get();
  def.commandRing = commands_.get();
}

void ReplayCapture::start() {
  logger_->startWriter(*inputs_, commands_.get());
  started_ = true;
}

std::string ReplayCapture::finish(std::uint64_t droppedInputs) {
  if (finished_) return "";
  finished_ = true;
  try {
    if (started_) logger_->stopWriter();
    logger_->drain(*inputs_, commands_.get());
    logger_->finish(droppedInputs);
  } catch (const record::RecordError& e) {
    return e.what();
  }
  return "";
}

}  // namespace hemiroll::game
