#include "game/research/report/SvgDocument.h"

#include <charconv>
#include <cmath>

namespace hemiroll::report {

namespace {

bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

std::string escapeXml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters are not allowed in XML 1.0 text (tab and line breaks are).
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n' || c == '\r') out += c;
    }
  }
  return out;
}

SvgDocument::SvgDocument(double width, double height) : width_(width), height_(height) {}

void SvgDocument::number(double v) {
  if (!std::isfinite(v)) v = 0.0;  // callers skip non-finite elements; this is the last guard
  char buffer[32];
  double rounded = std::round(v * 100.0) / 100.0;  // 0.01 px
  if (rounded == 0.0) rounded = 0.0;              // no "-0"
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, rounded, std::chars_format::fixed, 2);
  std::string_view text(buffer, static_cast<std::size_t>(r.ptr - buffer));
  // "12.50" -> "12.5", "3.00" -> "3": trailing zeros carry nothing.
  while (text.back() == '0') text.remove_suffix(1);
  if (text.back() == '.') text.remove_suffix(1);
  body_ += text;
}

void SvgDocument::attribute(std::string_view name, double v) {
  body_ += ' ';
  body_ += name;
  body_ += "=\"";
  number(v);
  body_ += '"';
}

void SvgDocument::styleAttributes(const Style& s) {
  body_ += " stroke=\"" + escapeXml(s.stroke) + "\" fill=\"" + escapeXml(s.fill) + "\"";
  if (s.stroke != "none") attribute("stroke-width", std::isfinite(s.strokeWidth) ? s.strokeWidth : 1.0);
  if (s.opacity < 1.0 && std::isfinite(s.opacity)) attribute("opacity", std::max(0.0, s.opacity));
  if (!s.dash.empty()) body_ += " stroke-dasharray=\"" + escapeXml(s.dash) + "\"";
}

void SvgDocument::rect(const Rect& r, const Style& style) {
  if (!finite({r.x, r.y}) || !finite({r.width, r.height}) || r.width < 0.0 || r.height < 0.0) return;
  body_ += "<rect";
  attribute("x", r.x), attribute("y", r.y), attribute("width", r.width), attribute("height", r.height);
  styleAttributes(style);
  body_ += "/>\n";
}

void SvgDocument::line(Point a, Point b, const Style& style) {
  if (!finite(a) || !finite(b)) return;
  body_ += "<line";
  attribute("x1", a.x), attribute("y1", a.y), attribute("x2", b.x), attribute("y2", b.y);
  styleAttributes(style);
  body_ += "/>\n";
}

void SvgDocument::polyline(std::span<const Point> points, const Style& style) {
  if (points.size() < 2) return;
  for (const Point& p : points)
    if (!finite(p)) return;
  body_ += "<polyline points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) body_ += ' ';
    number(points[i].x);
    body_ += ',';
    number(points[i].y);
  }
  body_ += '"';
  styleAttributes(style);
  body_ += " stroke-linejoin=\"round\"/>\n";
}

void SvgDocument::circle(Point centre, double radius, const Style& style) {
  if (!finite(centre) || !std::isfinite(radius) || radius < 0.0) return;
  body_ += "<circle";
  attribute("cx", centre.x), attribute("cy", centre.y), attribute("r", radius);
  styleAttributes(style);
  body_ += "/>\n";
}

void SvgDocument::text(Point at, std::string_view text, const TextStyle& style) {
  if (!finite(at)) return;
  body_ += "<text";
  attribute("x", at.x), attribute("y", at.y), attribute("font-size", style.size);
  body_ += " font-family=\"sans-serif\" fill=\"" + escapeXml(style.fill) + "\"";
  if (style.anchor != Anchor::Start) body_ += style.anchor == Anchor::Middle ? " text-anchor=\"middle\"" : " text-anchor=\"end\"";
  if (style.bold) body_ += " font-weight=\"bold\"";
  if (style.rotate != 0.0 && std::isfinite(style.rotate)) {
    body_ += " transform=\"rotate(";
    number(style.rotate);
    body_ += ' ';
    number(at.x);
    body_ += ' ';
    number(at.y);
    body_ += ")\"";
  }
  body_ += '>' + escapeXml(text) + "</text>\n";
}

void SvgDocument::beginClip(const Rect& r) {
  const std::string id = "clip" + std::to_string(++clips_);
  body_ += "<clipPath id=\"" + id + "\"><rect";
  attribute("x", r.x), attribute("y", r.y), attribute("width", r.width), attribute("height", r.height);
  body_ += "/></clipPath>\n<g clip-path=\"url(#" + id + ")\">\n";
  ++openClips_;
}

void SvgDocument::endClip() {
  if (openClips_ == 0) return;
  --openClips_;
  body_ += "</g>\n";
}

std::string SvgDocument::str() const {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"";
  SvgDocument header(0, 0);
  header.attribute("width", width_);
  header.attribute("height", height_);
  out += header.body_;
  out += " viewBox=\"0 0 ";
  header.body_.clear();
  header.number(width_);
  header.body_ += ' ';
  header.number(height_);
  out += header.body_ + "\">\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out += body_;
  for (int i = 0; i < openClips_; ++i) out += "</g>\n";  // a clip left open still closes
  out += "</svg>\n";
  return out;
}

}  // namespace hemiroll::report
