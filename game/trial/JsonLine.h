#pragma once
// One JSON object on one line, for machine-read results (`hemiroll run`).
// Strings are escaped per RFC 8259 (quote, backslash, control characters;
// other bytes pass through, so UTF-8 stays UTF-8). Numbers are written in
// the shortest form that reads back to the same double (0.1, not
// 0.10000000000000001), or rounded to a number of decimals where more would
// be noise (a simulated time summed tick by tick: 9.358, not
// 9.3580000000002528); a non-finite number is written as null, because JSON
// has no NaN or Infinity.

#include <string>
#include <string_view>

namespace hemiroll::game {

class JsonLine {
 public:
  JsonLine& add(std::string_view key, std::string_view value);
  JsonLine& add(std::string_view key, const char* value) { return add(key, std::string_view(value)); }
  JsonLine& add(std::string_view key, double value);
  // Rounded to `decimals` places, trailing zeros dropped.
  JsonLine& add(std::string_view key, double value, int decimals);
  JsonLine& add(std::string_view key, long long value);
  JsonLine& addNull(std::string_view key);
  // true / false (a separate name: a bool overload would catch pointers).
  JsonLine& addBool(std::string_view key, bool value);

  // "{...}" without a newline.
  std::string str() const { return text_ + "}"; }

  static std::string quote(std::string_view text);
  static std::string number(double value);
  static std::string number(double value, int decimals);

 private:
  void key(std::string_view name);
  std::string text_ = "{";
};

}  // namespace hemiroll::game
