#pragma once
// An SVG 1.1 document built element by element. Coordinates are pixels
// (origin top left); numbers are written with two decimals through
// std::to_chars (no locale), and an element with a non-finite coordinate is
// left out rather than written with "nan" in it. Text is escaped.

#include <span>
#include <string>
#include <string_view>

namespace hemiroll::report {

struct Point {
  double x = 0.0, y = 0.0;
};

struct Rect {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
  double right() const { return x + width; }
  double bottom() const { return y + height; }
};

struct Style {
  std::string stroke = "none";   // colour ("#1f77b4", "black") or "none"
  std::string fill = "none";
  double strokeWidth = 1.0;      // [px]
  double opacity = 1.0;          // 0..1, for fill and stroke
  std::string dash{};              // e.g. "4 3"; empty for solid
};

enum class Anchor { Start, Middle, End };

struct TextStyle {
  double size = 12.0;            // [px]
  Anchor anchor = Anchor::Start;
  std::string fill = "#222222";
  bool bold = false;
  double rotate = 0.0;           // [deg] about the anchor point
};

class SvgDocument {
 public:
  SvgDocument(double width, double height);

  double width() const { return width_; }
  double height() const { return height_; }

  void rect(const Rect& r, const Style& style);
  void line(Point a, Point b, const Style& style);
  // Points must be finite (LinePlot breaks its lines at non-finite data).
  void polyline(std::span<const Point> points, const Style& style);
  void circle(Point centre, double radius, const Style& style);
  void text(Point at, std::string_view text, const TextStyle& style);
  // Everything drawn until endClip() is clipped to r.
  void beginClip(const Rect& r);
  void endClip();

  // The whole document, with the XML declaration.
  std::string str() const;

 private:
  void number(double v);
  void attribute(std::string_view name, double v);
  void styleAttributes(const Style& style);

  double width_, height_;
  std::string body_{};
  int clips_ = 0;       // ids handed out
  int openClips_ = 0;
};

// Text with &, <, >, " and ' escaped for XML.
std::string escapeXml(std::string_view text);

}  // namespace hemiroll::report
