#include "game/trial/JsonLine.h"

#include "engine/files/PrintableName.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace hemiroll::game {

// Text that is not valid UTF-8 (a file name of other bytes) would make the
// line invalid JSON: each such byte is written as \xNN first (the one rule,
// engine/files/PrintableName.h), its backslash then escaped as JSON's.
std::string JsonLine::quote(std::string_view raw) {
  const std::string text = files::validUtf8(raw);
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string JsonLine::number(double value) {
  if (!std::isfinite(value)) return "null";
  char text[40];
  const std::to_chars_result r = std::to_chars(text, text + sizeof text, value);
  return std::string(text, r.ptr);
}

std::string JsonLine::number(double value, int decimals) {
  if (!std::isfinite(value)) return "null";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", std::clamp(decimals, 0, 17), value);
  std::string out = text;
  if (out.find('.') != std::string::npos) {
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
  }
  if (out == "-0") out = "0";
  return out;
}

void JsonLine::key(std::string_view name) {
  if (text_.size() > 1) text_ += ",";
  text_ += quote(name);
  text_ += ":";
}

JsonLine& JsonLine::add(std::string_view name, std::string_view value) {
  key(name);
  text_ += quote(value);
  return *this;
}

JsonLine& JsonLine::add(std::string_view name, double value) {
  key(name);
  text_ += number(value);
  return *this;
}

JsonLine& JsonLine::add(std::string_view name, double value, int decimals) {
  key(name);
  text_ += number(value, decimals);
  return *this;
}

JsonLine& JsonLine::add(std::string_view name, long long value) {
  key(name);
  text_ += std::to_string(value);
  return *this;
}

JsonLine& JsonLine::addBool(std::string_view name, bool value) {
  key(name);
  text_ += value ? "true" : "false";
  return *this;
}

JsonLine& JsonLine::addNull(std::string_view name) {
  key(name);
  text_ += "null";
  return *this;
}

}  // namespace hemiroll::game
