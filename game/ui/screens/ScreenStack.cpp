#include "game/ui/screens/ScreenStack.h"

namespace hemiroll::game {

void ScreenStack::push(std::unique_ptr<Screen> s) { pending_.push_back({Op::Push, std::move(s)}); }
void ScreenStack::pop() { pending_.push_back({Op::Pop, nullptr}); }
void ScreenStack::replace(std::unique_ptr<Screen> s) { pending_.push_back({Op::Replace, std::move(s)}); }
void ScreenStack::reset(std::unique_ptr<Screen> s) { pending_.push_back({Op::Reset, std::move(s)}); }

void ScreenStack::apply() {
  // Taken out first: enter() may ask for further changes (next frame's).
  std::vector<Change> changes;
  changes.swap(pending_);
  for (Change& c : changes) {
    Screen* before = top();
    if (c.op == Op::Pop || c.op == Op::Replace) {
      if (!screens_.empty()) {
        screens_.back()->leave();
        screens_.pop_back();
      }
    } else if (c.op == Op::Reset) {
      while (!screens_.empty()) {
        screens_.back()->leave();
        screens_.pop_back();
      }
    } else if (before) {
      before->leave();  // covered by the pushed screen
    }
    if (c.screen) screens_.push_back(std::move(c.screen));
    if (top() && top() != before) top()->enter();
  }
}

void ScreenStack::visible(std::vector<Screen*>& out) const {
  out.clear();
  std::size_t first = screens_.size();
  while (first > 0) {
    --first;
    if (!screens_[first]->overlay()) break;
  }
  for (std::size_t i = first; i < screens_.size(); ++i) out.push_back(screens_[i].get());
}

}  // namespace hemiroll::game
