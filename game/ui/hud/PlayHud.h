#pragma once
// The play screen's HUD (Dear ImGui), in a player's words and units:
//  - top left: the level, a short form of its task (taskGoal: it stays on
//    screen), the clock, the distance to the target, what is out of its band
//    and what to do about it, in screen directions (PlayerWords; the table
//    of every judged component, in the physics' names, one key away), the
//    settle meter (the hold filling up while every component is inside, or
//    what broke the last hold and by how much), a tilt gauge, the
//    engagement, the ghost's and the autopilot's lines, a loop-timing note;
//  - beside it, top: the level's messages, never over the HUD;
//  - under the messages: a prompt when the player must act (take hold to
//    start, take hold again after letting go or a stop);
//  - bottom right: the level's `scene.plots` (contact x and y when it names
//    none) with their axis values, and the mass point on the face; or, when
//    asked for, the full table in their place, right of the hemisphere.
// Every panel keeps clear of the hemisphere (setKeepClear: its rect on
// screen, HudLayout) and wraps its text (WrappedText), never cuts it; sizes
// grow with the interface scale (uiScale).
// update() computes a plain HudReadout (tested without a window); draw()
// shows it and notes where each window went (rects(), for layout tests).
// Ring buffers are fixed once a level is set: no allocation per frame.

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/haptics/ServoSnapshot.h"
#include "engine/physics/HemisphereParams.h"
#include "engine/physics/RollingDynamics.h"
#include "engine/task/TaskJudge.h"
#include "game/ui/hud/HudChannel.h"
#include "game/ui/hud/PlayerWords.h"
#include "game/ui/hud/ScrollingPlot.h"
#include "game/ui/hud/WindowRects.h"

namespace hemiroll::game {

struct HudReadout {
  double time = 0.0, timeLimit = 0.0;  // [s]
  double distanceToTarget = -1.0;      // contact point to its target [m]; < 0: no contact target
  int componentsInside = 0, components = 0;
  bool allInside = false;
  double precessionRate = 0.0;         // d psi / dt [rad/s]
  double holdTime = 0.0, requiredHold = 0.0;  // [s]
  task::HoldBreak holdBreak;         // the last hold lost in this stage
  Tilt tilt;
  bool loopWarning = false;            // late ticks or missed ticks seen
  double latenessMs = 0.0;             // the snapshot's worst lateness so far [ms]
  unsigned long long missedTicks = 0;
  unsigned long long stalls = 0;       // wake-ups past the overrun limit (ridden out without force)
  haptics::Engagement engagement = haptics::Engagement::Disengaged;
  double rampScale = 0.0;
};

class PlayHud {
 public:
  static constexpr double kLateWarning = 0.0005;  // [s]: a tick later than half a period is worth showing
  static constexpr double kHoldBreakShown = 3.0;  // [s] a lost hold stays explained
  static constexpr std::size_t kMaxPlots = 3;
  static constexpr int kCompactRows = 3;          // out-of-band rows the compact HUD lists

  PlayHud();
  void reset();
  // Once per frame, from the latest snapshot and the judge.
  void update(const haptics::ServoSnapshot& snapshot, const task::TaskJudge& judge);
  const HudReadout& readout() const { return readout_; }

  // Text the HUD names; set when a session starts.
  void setLabels(std::string level, std::string device, std::string method, bool mousePlayer, double faceRadius);
  // The level's plot channels (scene.plots: names LevelLoader accepted; the
  // first kMaxPlots) and its model (for the energy channel).
  void setPlots(const std::vector<std::string>& channels, const physics::HemisphereParams& params);
  // The key that takes hold, by name, for the hint while disengaged.
  void setTakeHoldKey(const std::string& name) { takeHoldHint_ = "click or " + name + " to take hold"; }
  const std::string& takeHoldHint() const { return takeHoldHint_; }
  // The key that shows the full table, by name (the compact HUD says it).
  void setTableKey(const std::string& name) { tableKey_ = name; }
  // The heading of screen right [rad], so that the tilt gauge leans the way
  // the screen shows.
  void setScreenYaw(double radians) { screenYaw_ = radians; }
  void toggleTable() { fullTable_ = !fullTable_; }
  bool fullTable() const { return fullTable_; }
  // A call to act, drawn large in the upper middle ("" = none).
  void setPrompt(std::string text) { prompt_ = std::move(text); }
  const std::string& prompt() const { return prompt_; }
  // The short form of the task now (taskGoal), under the level's name.
  void setGoal(std::string text) { goal_ = std::move(text); }
  const std::string& goal() const { return goal_; }
  // The hemisphere's rect on screen this frame [window px] (hemisphereRect):
  // no panel is placed over it. Zero size: nothing to keep clear.
  void setKeepClear(const WindowRect& r) { keepClear_ = r; }
  const WindowRect& keepClear() const { return keepClear_; }
  // The compact rows of the last update(), in the player's words.
  std::span<const AdviceRow> adviceRows() const { return {advice_.data(), static_cast<std::size_t>(adviceCount_)}; }
  void draw(double fps);
  // The windows drawn by the last draw(), by name.
  std::span<const WindowRect> rects() const { return rects_.rects(); }
  // For the windows drawn over the HUD's frame by others (the hint compass).
  WindowRects& windowRects() { return rects_; }

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

  std::size_t plotCount() const { return channels_.size(); }
  const HudChannel& plotChannel(std::size_t i) const { return channels_[i]; }
  const ScrollingPlot& plot(std::size_t i) const { return plots_[i]; }

  // One judged component for the full table, in its physics name and the
  // player's unit, e.g. "contact x (u_a) -28.0 mm, wants -40.0 ±4.0 mm";
  // written into `out` (no allocation) or returned.
  static void componentLine(const task::ComponentStatus& c, std::span<char> out);
  static std::string componentLine(const task::ComponentStatus& c);
  // Why the last hold was lost, e.g. "the tilt went out by 0.40 ° after 0.6 s".
  static void holdBreakLine(const task::HoldBreak& b, std::span<char> out);
  static std::string holdBreakLine(const task::HoldBreak& b);
  // Decimals for a plot axis spanning `range` (in its unit) so its ends differ.
  static int axisDecimals(double range);
  // `value` as drawn with `decimals`: 0 when it rounds to zero (no "-0.0").
  static double shownAs(double value, int decimals);

 private:
  void drawStatus();
  void drawComponents();
  void drawSettleMeter();
  void drawTiltGauge();
  void drawLoopNote();
  WindowRect drawTable(const WindowRect& messages);         // none drawn: an empty rect
  WindowRect drawMessages(float left, float right);         // none drawn: an empty rect at the top
  void drawPrompt(const WindowRect& hud, const WindowRect& messages, const WindowRect& plots,
                  const WindowRect& table);
  WindowRect drawPlots();

  HudReadout readout_;
  std::array<task::ComponentStatus, 16> components_{};
  int componentCount_ = 0;
  std::array<AdviceRow, 8> advice_{};
  int adviceCount_ = 0;
  WindowRect keepClear_;
  std::vector<HudChannel> channels_;
  std::vector<ScrollingPlot> plots_;
  ScrollingPlot faceX_, faceY_;
  std::optional<physics::RollingDynamics> dynamics_;
  double lastPsi_ = 0.0, lastTime_ = -1.0;
  std::string level_, device_, method_, ghost_, autopilot_, prompt_, goal_;
  std::string takeHoldHint_ = "click or Space to take hold";
  std::string tableKey_ = "I";
  bool mousePlayer_ = true;
  bool fullTable_ = false;
  double screenYaw_ = 0.0;
  std::optional<double> score_;
  double fps_ = 0.0;
  struct { float x = 0, y = 0; } promptSize_, tableSize_;  // [px] as last drawn
  std::array<std::string, kMessages> messages_{};
  std::array<double, kMessages> messageUntil_{};
  std::size_t nextMessage_ = 0;
  double faceRadius_ = 0.04;  // R [m]: the face plot's circle
  WindowRects rects_;
};

}  // namespace hemiroll::game
