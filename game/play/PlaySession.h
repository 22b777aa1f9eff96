#pragma once
// A human playing a level in real time with the mouse: the shape of
// RealtimeTrial with MouseDevice instead of a bot.
//   servo thread:  MouseDevice (the UI's latest pointer, lock-free) ->
//                  coupling -> physics -> safety -> snapshot + a RecordRow
//                  of every tick into a lock-free ring;
//   UI thread:     pointer events -> PointerMapping -> MouseDevice;
//                  once per frame: RingJudge drains the ring (every tick
//                  judged, level callbacks at their rate), latest snapshot
//                  for the renderer and the HUD.
// frame() never waits for the servo loop. A safety fault (a watchdog: the
// loop starved, stale input) does not end the trial: the loop has already
// taken the force off and stopped; fault() says which, and resume() clears
// it and goes on (the player takes hold again). Engagement follows the loop's
// rule: a click arms it, and it engages when the proxy reaches the mass
// point; the force then ramps in (ServoSnapshot::rampScale).

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include "engine/haptics/MouseDevice.h"
#include "engine/haptics/PointerMapping.h"
#include "engine/haptics/ServoLoop.h"
#include "game/play/ReplayCapture.h"
#include "game/play/RingJudge.h"

namespace hemiroll::game {

struct PlaySessionDef {
  haptics::PointerMappingDef pointer;  // centre is set from the window size
  int windowWidth = 1280, windowHeight = 720;  // [window px]
  bool requestRealtime = true;         // SCHED_FIFO for the servo thread when permitted
  std::optional<physics::CouplingDef> coupling;  // the player's settings; none = the level's
  // Log the trial for a replay here ("" = no replay); levelHash goes into
  // its header (levelFileHash of the level file).
  std::filesystem::path replayFile;
  std::string levelHash;
  // Recording (a research session's trial): every recordEvery-th judged
  // tick is forwarded into this ring, which a TrialRecorder's writer thread
  // drains. nullptr = not recorded.
  haptics::RecordRing* recordRing = nullptr;
  int recordEvery = 10;
};

class PlaySession {
 public:
  // `level` must outlive the session. Throws std::invalid_argument for a
  // level the loop refuses (its message names the field).
  PlaySession(script::LoadedLevel& level, const PlaySessionDef& def);
  ~PlaySession();

  void start();  // on_start, then the servo thread
  // UI thread: the pointer [window px]; buttons bit 0 = left.
  void pointer(double px, double py, bool jump = false);
  void wheel(double notches);
  void resize(int width, int height);
  void click();        // arm the engagement (the loop engages near the mass point)
  void release();      // disengage: the force ramps out
  void pause();        // physics stops, force zero at once
  void resume();       // also clears a latched safety fault
  // The latched fault of the latest snapshot; None once resume() asked to
  // clear it (snapshots older than the clearing tick still show it).
  haptics::SafetyFault fault() const {
    return snapshot_.tick <= faultClearedBy_ ? haptics::SafetyFault::None : snapshot_.fault;
  }
  void quit();         // ends the trial as a failure ("quit by the player")

  // Once per frame: judge what the loop produced; returns true while running.
  bool frame();
  const haptics::ServoSnapshot& snapshot() const { return snapshot_; }
  const RingJudge& judging() const { return judging_; }
  bool paused() const { return paused_; }
  bool finished() const { return judging_.finished(); }
  // Stops the loop (idempotent) and returns the result.
  TrialResult finish();
  haptics::LoopTimingSummary timing() const { return loop_->timingSummary(); }
  const char* realtimeNote() const { return loop_->realtime().note; }
  // After finish(): the replay log when one was asked for and came out
  // usable, else "" (replayError() says why).
  std::filesystem::path replayFile() const { return replayError_.empty() && capture_ ? capture_->file() : ""; }
  const std::string& replayError() const { return replayError_; }
  // The proxy's scene position under the pointer now [m] (for tests).
  haptics::Vec3 pointerScene() const;

 private:
  void post(haptics::ServoCommandKind kind);

  script::LoadedLevel& level_;
  haptics::ServoLoopDef loopDef_;
  haptics::PointerMapping mapping_;
  std::unique_ptr<haptics::RecordRing> ring_;
  std::unique_ptr<ReplayCapture> capture_;
  std::string replayError_;
  haptics::MouseDevice device_;
  std::unique_ptr<haptics::ServoLoop> loop_;
  RingJudge judging_;
  haptics::ServoSnapshot snapshot_;
  physics::ForceDrivenState initial_;
  double lastPx_ = 0.0, lastPy_ = 0.0;
  bool paused_ = false, stopped_ = false;
  std::uint64_t faultClearedBy_ = 0;  // the tick by which a ClearFault has been applied
  std::chrono::steady_clock::time_point started_;
};

}  // namespace hemiroll::game
