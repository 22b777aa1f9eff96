#pragma once
// The stack of screens. Changes asked for during a frame (a button pressed in
// paint(), a key in input()) are applied at the start of the next frame, so
// a screen is never destroyed while its own code runs.

#include <memory>
#include <vector>

#include "game/ui/screens/Screen.h"

namespace hemiroll::game {

class ScreenStack {
 public:
  void push(std::unique_ptr<Screen> screen);
  void pop();
  // Pops the top and pushes `screen` in its place.
  void replace(std::unique_ptr<Screen> screen);
  // Everything off, then `screen` (back to the title).
  void reset(std::unique_ptr<Screen> screen);

  // Applies the changes asked for; calls leave()/enter() as screens change.
  void apply();
  Screen* top() const { return screens_.empty() ? nullptr : screens_.back().get(); }
  bool empty() const { return screens_.empty(); }
  std::size_t size() const { return screens_.size(); }
  // The screens to paint this frame: from the topmost non-overlay upwards,
  // into `out` (cleared; reused across frames, so no allocation once warm).
  void visible(std::vector<Screen*>& out) const;

 private:
  enum class Op { Push, Pop, Replace, Reset };
  struct Change {
    Op op;
    std::unique_ptr<Screen> screen;
  };
  std::vector<std::unique_ptr<Screen>> screens_;
  std::vector<Change> pending_;
};

}  // namespace hemiroll::game
