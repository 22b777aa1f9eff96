#pragma once
// Text wrapped to a width, never cut, and never split where a player would
// misread it (issue 27: "5.\n75 s", "4\ncm", and lines cut at a panel's
// edge). Dear ImGui's own wrap breaks after '.' and ',' (inside numbers) and
// at any space (between a number and its unit); this one breaks only at a
// space that does not follow a digit, so "12.5 mm", "±4.0 mm)" and "at 9.10
// s:" stay whole. A word wider than the line stands alone on it (then the
// panel, not the text, must give way: the layout tests check that none does).

#include <functional>
#include <string_view>

struct ImVec4;  // imgui.h, which the window's library keeps private

namespace hemiroll::game {

// Calls `line` for each line of `text` wrapped to `width` by `measure`
// (the width of a piece of text, in the unit of `width`); '\n' breaks too.
// Lines carry no leading or trailing break space. No allocation.
void wrapLines(std::string_view text, float width, const std::function<float(std::string_view)>& measure,
               const std::function<void(std::string_view)>& line);

// Inside an ImGui window: `text` wrapped to `width` [px] (<= 0: to the
// content region's right edge), in the current text colour.
void wrappedText(std::string_view text, float width = 0.0f);
void wrappedText(const ImVec4& colour, std::string_view text, float width = 0.0f);
void wrappedTextDisabled(std::string_view text, float width = 0.0f);
// printf-style (formatted into a stack buffer of 1 KiB), to the content region's edge.
void wrappedTextf(const char* format, ...) __attribute__((format(printf, 1, 2)));
void wrappedTextColoredf(const ImVec4& colour, const char* format, ...) __attribute__((format(printf, 2, 3)));
void wrappedTextDisabledf(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace hemiroll::game
