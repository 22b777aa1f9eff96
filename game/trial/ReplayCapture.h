#pragma once
// Logs a real-time trial for replay (engine/record's ReplayLogger): the loop
// pushes every tick's device reading and every applied command into rings
// owned here; a writer thread drains them into the log file. The level's
// file hash goes into the header, so that a replay is only played against
// the level it was recorded on.

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "engine/haptics/devices/DeviceNames.h"
#include "engine/haptics/RecordRow.h"
#include "engine/haptics/ServoLoop.h"

namespace hemiroll::record {
class ReplayLogger;
}

namespace hemiroll::game {

class ReplayCapture {
 public:
  // Creates the log file (an existing one is replaced). Throws
  // record::RecordError naming the file.
  ReplayCapture(const std::filesystem::path& file, const std::string& levelHash, double dt,
                const std::string& deviceKind = haptics::kMouseDevice);
  ~ReplayCapture();

  // Points the loop's input and command rings here (before constructing it).
  void attach(haptics::ServoLoopDef& def);
  void start();
  // After the loop stopped: drains, completes the file. "" = a usable
  // replay, else why not (inputs dropped, I/O).
  std::string finish(std::uint64_t droppedInputs);
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::unique_ptr<haptics::InputRing> inputs_;
  std::unique_ptr<haptics::CommandRing> commands_;
  std::unique_ptr<record::ReplayLogger> logger_;
  bool started_ = false, finished_ = false;
};

}  // namespace hemiroll::game
