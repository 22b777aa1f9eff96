#include "game/ui/hud/WrappedText.h"

#include <imgui.h>

#include <array>
#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace hemiroll::game {

namespace {

// A space may break a line unless it follows a digit (a number and its
// unit, or a number and the word it counts, stay together).
bool breakable(std::string_view text, std::size_t i) {
  return text[i] == ' ' && (i == 0 || !std::isdigit(static_cast<unsigned char>(text[i - 1])));
}

void wrapParagraph(std::string_view p, float width, const std::function<float(std::string_view)>& measure,
                   const std::function<void(std::string_view)>& line) {
  std::size_t start = 0;
  while (start < p.size() && p[start] == ' ') ++start;
  std::size_t fits = std::string_view::npos;  // the last break whose line fits
  std::size_t i = start;
  while (i <= p.size()) {
    const bool end = i == p.size();
    if (!end && !breakable(p, i)) {
      ++i;
      continue;
    }
    if (measure(p.substr(start, i - start)) <= width || (fits == std::string_view::npos && end)) {
      if (end) break;
      fits = i;
      ++i;
      continue;
    }
    // [start, i) is too wide: break at the last fit, or (one piece wider
    // than the line) here.
    const std::size_t cut = fits != std::string_view::npos ? fits : i;
    line(p.substr(start, cut - start));
    start = cut;
    while (start < p.size() && p[start] == ' ') ++start;
    fits = std::string_view::npos;
    i = std::max(i, start);
    if (cut == i && i < p.size()) ++i;
  }
  if (start < p.size()) line(p.substr(start));
}

// Lines joined with '\n' into a stack buffer and drawn as one text item
// (one item keeps ImGui's line spacing); a text longer than the buffer is
// drawn in parts.
class LineBuffer {
 public:
  void add(std::string_view l) {
    if (used_ + l.size() + 2 > buffer_.size()) flush();
    if (l.size() + 2 > buffer_.size()) {  // longer than the whole buffer: on its own
      ImGui::TextUnformatted(l.data(), l.data() + l.size());
      return;
    }
    if (used_ > 0) buffer_[used_++] = '\n';
    std::memcpy(buffer_.data() + used_, l.data(), l.size());
    used_ += l.size();
  }
  void flush() {
    if (used_ == 0) return;
    ImGui::TextUnformatted(buffer_.data(), buffer_.data() + used_);
    used_ = 0;
  }

 private:
  std::array<char, 2048> buffer_{};
  std::size_t used_ = 0;
};

}  // namespace

void wrapLines(std::string_view text, float width, const std::function<float(std::string_view)>& measure,
               const std::function<void(std::string_view)>& line) {
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t nl = text.find('\n', start);
    const std::string_view p = text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start);
    if (p.empty())
      line(p);
    else
      wrapParagraph(p, width, measure, line);
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
}

void wrappedText(std::string_view text, float width) {
  if (width <= 0.0f) width = ImGui::GetContentRegionAvail().x;
  LineBuffer buffer;
  wrapLines(
      text, width,
      [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; },
      [&](std::string_view l) { buffer.add(l); });
  buffer.flush();
}

void wrappedText(const ImVec4& colour, std::string_view text, float width) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  wrappedText(text, width);
  ImGui::PopStyleColor();
}

void wrappedTextDisabled(std::string_view text, float width) {
  wrappedText(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), text, width);
}

namespace {

std::string_view format(std::array<char, 1024>& buffer, const char* fmt, std::va_list args) {
  const int n = std::vsnprintf(buffer.data(), buffer.size(), fmt, args);
  if (n < 0) return {};
  return std::string_view(buffer.data(), std::min<std::size_t>(static_cast<std::size_t>(n), buffer.size() - 1));
}

}  // namespace

void wrappedTextf(const char* fmt, ...) {
  std::array<char, 1024> buffer{};
  std::va_list args;
  va_start(args, fmt);
  const std::string_view text = format(buffer, fmt, args);
  va_end(args);
  wrappedText(text);
}

void wrappedTextColoredf(const ImVec4& colour, const char* fmt, ...) {
  std::array<char, 1024> buffer{};
  std::va_list args;
  va_start(args, fmt);
  const std::string_view text = format(buffer, fmt, args);
  va_end(args);
  wrappedText(colour, text);
}

void wrappedTextDisabledf(const char* fmt, ...) {
  std::array<char, 1024> buffer{};
  std::va_list args;
  va_start(args, fmt);
  const std::string_view text = format(buffer, fmt, args);
  va_end(args);
  wrappedTextDisabled(text);
}

}  // namespace hemiroll::game
