#pragma once
// game/ui/screens: the game's screens as state objects (Neverball's "state"
// idea): each has enter/leave/input/update/paint hooks and lives on a
// ScreenStack. A screen knows its ScreenHost (the services: window, renderer,
// audio, scores, settings) and may ask the stack to change; it must not
// touch SDL directly (input arrives as platform::InputEvent, so tests drive
// screens with the same events a player makes).
//
// Screens: Title -> LevelSelect -> Play (+ Pause overlay) -> Results;
// Settings and Research from the title.

#include "engine/platform/InputEvent.h"

namespace hemiroll::game {

class ScreenHost;

// How many frames a screen needs (the App paces the main thread to it, so
// that the servo thread keeps a core): Play draws a moving scene at the
// player's frame cap; Watch is a scene the player only looks at (the
// autopilot playing: its planner needs the CPU more than the eye needs 60
// frames); Menu is a menu's hover and clicks (a few dozen a second); Still
// is a picture that does not change (paused).
enum class FrameNeed { Play, Watch, Menu, Still };

class Screen {
 public:
  explicit Screen(ScreenHost& host) : host_(host) {}
  virtual ~Screen() = default;
  Screen(const Screen&) = delete;
  Screen& operator=(const Screen&) = delete;

  virtual const char* name() const = 0;  // "title", "play", ... (tests and logs)
  virtual void enter() {}                // became the top screen (pushed, or the one above left)
  virtual void leave() {}                // another screen covers it, or it is removed
  virtual void input(const platform::InputEvent&) {}
  virtual void update(double /*dt*/) {}
  // GL drawing and ImGui calls for this frame (between the layer's begin/end).
  virtual void paint() = 0;
  // An overlay (pause) paints over the screen below it instead of hiding it.
  virtual bool overlay() const { return false; }
  // The frames this screen needs while it is the top one.
  virtual FrameNeed frameNeed() const { return FrameNeed::Menu; }

 protected:
  ScreenHost& host_;
};

}  // namespace hemiroll::game
