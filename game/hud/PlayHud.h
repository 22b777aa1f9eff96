#pragma once
// The play screen's HUD (Dear ImGui): time and limit, distance to target,
// per-component tolerance indicators (green inside, with the margin),
// precession rate, score so far, device and force method, a loop-timing
// warning from the snapshot, the force-arrow note for mouse players, a
// scrolling plot of one selectable state channel (the paper's Fig. 5: contact
// x by default) and a small plot of the mass point on the face.
//
// update() computes a plain HudReadout (tested without a window); draw()
// shows it. Ring buffers are fixed: no allocation per frame once warm.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/haptics/ServoSnapshot.h"
#include "engine/script/TaskJudge.h"
#include "game/hud/ScrollingPlot.h"

namespace hemiroll::game {

struct HudReadout {
  double time = 0.0, timeLimit = 0.0;  // [s]
  double distanceToTarget = -1.0;      // contact point to its target [m]; < 0: no contact target
  int componentsInside = 0, components = 0;
  double precessionRate = 0.0;         // d psi / dt [rad/s]
  double holdTime = 0.0, requiredHold = 0.0;  // [s]
  bool loopWarning = false;            // late ticks or missed ticks seen
  double latenessMs = 0.0;             // the snapshot's worst lateness so far [ms]
  unsigned long long missedTicks = 0;
  haptics::Engagement engagement = haptics::Engagement::Disengaged;
  double rampScale = 0.0;
};

class PlayHud {
 public:
  // Channels the big plot can show: 12-state slot indices.
  static constexpr std::array<int, 6> kChannels = {7, 8, 9, 10, 11, 0};  // u_a, v_a, u_o, v_o, psi, x_p
  static constexpr double kLateWarning = 0.0005;  // [s]: a tick later than half a period is worth showing

  PlayHud();
  void reset();
  // Once per frame, from the latest snapshot and the judge.
  void update(const haptics::ServoSnapshot& snapshot, const script::TaskJudge& judge);
  const HudReadout& readout() const { return readout_; }

  // Text the HUD names; set when a session starts.
  void setLabels(std::string level, std::string device, std::string method, bool mousePlayer, double faceRadius);
  // The key that takes hold, by name, for the hint while disengaged.
  void setTakeHoldKey(const std::string& name) { takeHoldHint_ = "click or " + name + " to take hold"; }
  const std::string& takeHoldHint() const { return takeHoldHint_; }
  void draw(double fps);

  // The ghost's line ("" = none): whose run it is, and how it is going.
  void setGhost(std::string line) { ghost_ = std::move(line); }
  // The autopilot's line ("" = none): it is playing, or the hint is on.
  void setAutopilot(std::string line) { autopilot_ = std::move(line); }
  const std::string& ghost() const { return ghost_; }
  const std::string& autopilot() const { return autopilot_; }
  const std::string& title() const { return level_; }  // the level's name, or "trial k of N: name"

  // The level's score function on the summary so far (none: no score function).
  void setScore(std::optional<double> score) { score_ = score; }
  // A level's message (hemiroll.message), shown until `until` [s, simulated];
  // the oldest of kMessages gives way.
  void addMessage(const std::string& text, double until);
  static constexpr std::size_t kMessages = 4;
  // The messages shown at simulated time `now`, oldest first (tests).
  std::vector<std::string> messages(double now) const;

  int channel() const { return channel_; }
  void setChannel(int index) { channel_ = index; plot_.clear(); }
  const ScrollingPlot& plot() const { return plot_; }

 private:
  HudReadout readout_;
  std::array<script::ComponentStatus, 16> components_{};
  int componentCount_ = 0;
  ScrollingPlot plot_, faceX_, faceY_;
  int channel_ = 0;
  double lastPsi_ = 0.0, lastTime_ = -1.0;
  std::string level_, device_, method_, ghost_, autopilot_;
  std::string takeHoldHint_ = "click or Space to take hold";
  bool mousePlayer_ = true;
  std::optional<double> score_;
  std::array<std::string, kMessages> messages_{};
  std::array<double, kMessages> messageUntil_{};
  std::size_t nextMessage_ = 0;
  double faceRadius_ = 0.04;  // R [m]: the face plot's circle
};

}  // namespace hemiroll::game
