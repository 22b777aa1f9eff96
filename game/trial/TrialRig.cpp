#include "game/trial/TrialRig.h"

#include <algorithm>
#include <exception>
#include <thread>

#include "engine/physics/StateKinematics.h"
#include "game/trial/ReplayCapture.h"
#include "game/trial/TrialSetup.h"

namespace hemiroll::game {

namespace {

// The level's loop with the rig's choices; the device's part follows once
// the device exists.
haptics::ServoLoopDef loopDefOf(const task::LevelDef& level, const TrialRigDef& def) {
  haptics::ServoLoopDef loop = trialLoopDef(level, def.device);
  if (def.coupling) loop.coupling = *def.coupling;
  if (def.safety) loop.safety = *def.safety;
  loop.guidance = def.guidance;
  loop.requestRealtime = def.threaded && def.requestRealtime;
  loop.clock = def.clock;
  return loop;
}

}  // namespace

TrialRig::TrialRig(script::LoadedLevel& level, const TrialRigDef& def, const RigDeviceMaker& makeDevice)
    : level_(level), def_(def), loopDef_(loopDefOf(level.def, def)), judging_(level, def.faultsEndTrial) {
  device_ = makeDevice(loopDef_);
  // Nothing to hold still on a device without force: a stall is caught up
  // (then the clock slows) instead of stopping the trial (ForceSafety).
  if (!device_->spec().hasForceOutput) loopDef_.maxCatchUpTicks = kForcelessCatchUpTicks;
  if (def.threaded) {
    judgeRing_ = std::make_unique<haptics::RecordRing>();
    loopDef_.recordRing = judgeRing_.get();
    loopDef_.recordEvery = 1;  // the judge sees every tick; the tap keeps the recording's rate
    if (!def.replayFile.empty()) {
      try {
        capture_ = std::make_unique<ReplayCapture>(def.replayFile, def.levelHash, loopDef_.period, def.device);
        capture_->attach(loopDef_);
      } catch (const std::exception& e) {
        capture_.reset();
        replayError_ = e.what();  // the trial goes on without a replay
      }
    }
  }
  loop_ = std::make_unique<haptics::ServoLoop>(loopDef_, *device_);
  initial_ = physics::forceStateOf(loopDef_.initialState);
  snapshot_.state = loopDef_.initialState;
}

TrialRig::~TrialRig() {
  loop_->stop();
  device_->close();  // on this thread (SDL's, for a joystick), after the loop let go of it
}

void TrialRig::record(const RecordTap& tap) {
  tap_ = tap;
  tap_.every = std::max(1, tap.every);
}

void TrialRig::post(haptics::ServoCommandKind kind) {
  haptics::ServoCommand c;
  c.kind = kind;
  loop_->post(c);
}

void TrialRig::step() {
  loop_->tick();
  loop_->latest(snapshot_);
  const bool judged = !judging_.finished();  // the tick that ends the trial is judged, and kept
  judging_.judgeTick(snapshot_);
  if (judged && tap_.ring != nullptr && snapshot_.tick % static_cast<std::uint64_t>(tap_.every) == 0)
    keep(haptics::recordRowOf(snapshot_));
}

void TrialRig::startLoop() {
  if (capture_) capture_->start();
  loop_->start();
}

void TrialRig::stopLoop() {
  if (stopped_) return;
  stopped_ = true;
  loop_->stop();
  loop_->latest(snapshot_);  // the last tick run
  if (capture_) replayError_ = capture_->finish(loop_->inputDropped());
}

std::size_t TrialRig::drain() {
  haptics::RecordRow row;
  std::size_t judged = 0;
  while (judgeRing_ && !judging_.finished() && judgeRing_->pop(row)) {
    judging_.judgeTick(row);
    keep(row);
    ++judged;
  }
  if (!judging_.finished() && loop_->recordDropped() > 0)
    judging_.fail("the judge fell behind the servo loop (ticks dropped)");
  return judged;
}

// A row the judge has judged, at the tap's rate.
void TrialRig::keep(const haptics::RecordRow& row) {
  if (tap_.ring == nullptr || row.tick % static_cast<std::uint64_t>(tap_.every) != 0) return;
  if (def_.threaded) {
    if (!tap_.ring->push(row)) ++tapLost_;
    return;
  }
  // Stepping runs as fast as the CPU allows: the recording's writer thread
  // frees room within its poll interval, and no row is lost.
  while (!tap_.ring->push(row)) std::this_thread::yield();
}

std::filesystem::path TrialRig::replayFile() const {
  return replayError_.empty() && capture_ ? capture_->file() : std::filesystem::path();
}

}  // namespace hemiroll::game
