#pragma once
// The layout rules of the window (issue 27) checked on every Dear ImGui
// window the last frame drew: it lies inside the display; its text is not
// cut (its content is no wider than the window's content region, nor taller
// unless it has a scrollbar to reach the rest); and it does not cover the
// hemisphere (`keepClear`, when given). One sentence per broken rule.

#include <string>
#include <vector>

#include "game/ui/hud/WindowRects.h"

namespace hemiroll::test {

std::vector<std::string> layoutProblems(float displayWidth, float displayHeight,
                                        const game::WindowRect* keepClear = nullptr);

// The names of the windows the last frame drew (for a test's message).
std::vector<std::string> drawnWindows();

}  // namespace hemiroll::test
