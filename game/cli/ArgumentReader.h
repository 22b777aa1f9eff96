#pragma once
// game/cli: reading a command line. Every hemiroll command and tool takes
// switches ("--realtime"), options ("--dt 0.001" or "--dt=0.001") and
// positional arguments in any order, and a wrong one is reported in one
// sentence that names it: "--dt needs a positive number of seconds, got 'x'".
//
// Owns: the reading loop and the value readers every command shares.
// Must not know: any command, file format or engine type (the commands turn
// the values into engine types themselves).

#include <array>
#include <cstdint>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hemiroll::cli {

// Takes an option's value. Returns "" when taken, else the whole sentence
// saying what is wrong (`needs()` builds the usual one).
using TakeValue = std::function<std::string(const std::string& flag, const std::string& value)>;

class ArgumentReader {
 public:
  // A switch takes no value ("--help", "--realtime").
  ArgumentReader& flag(std::string name, std::function<void()> set);
  // An option takes exactly one value. Aliases ("-h") are separate entries.
  ArgumentReader& option(std::string name, TakeValue take);
  // Arguments that do not start with '-' (and "-" itself, stdin by custom).
  // `what` names one in messages ("scenario file"); at most `count` of them.
  ArgumentReader& positional(std::string what, std::size_t count, std::function<void(const std::string&)> take);

  // Reads args from left to right; "" or the first error. An unknown flag,
  // a missing value, a value given to a switch and one positional too many
  // are errors; "--" ends the flags (what follows is positional).
  std::string read(const std::vector<std::string>& args) const;

 private:
  struct Entry {
    std::string name;
    std::function<void()> set;  // switch
    TakeValue take;             // option
  };
  const Entry* find(std::string_view name) const;

  std::vector<Entry> entries_;
  std::string positionalWhat_;
  std::size_t positionalCount_ = 0;
  std::function<void(const std::string&)> takePositional_;
};

// "<flag> needs <what>, got '<value>'": the one way a bad value is reported.
std::string needs(const std::string& flag, std::string_view what, const std::string& value);

// Value readers: true and `out` set when the WHOLE text is one such value.
bool readNumber(std::string_view text, double& out);        // finite decimal or exponent form
bool readInteger(std::string_view text, long long& out);    // decimal digits with an optional '-'
bool readUnsigned(std::string_view text, unsigned long long& out);  // decimal digits only
// "1280x720"
bool readSize(std::string_view text, int& width, int& height);
// "x,y,z": exactly N finite numbers separated by commas.
template <std::size_t N>
bool readNumbers(std::string_view text, std::array<double, N>& out);
// Splits on `separator`, keeping empty items (so "a,,b" has three).
std::vector<std::string> splitList(std::string_view text, char separator);

// Options for the common cases; each stores into `target` and reports with needs().
// A finite number in [min, max] (inclusive), described as `what`.
TakeValue numberIn(double& target, double min, double max, std::string what);
TakeValue numberIn(std::optional<double>& target, double min, double max, std::string what);
// A finite number > 0 ("a positive number of seconds").
TakeValue positiveNumber(double& target, std::string what);
TakeValue positiveNumber(std::optional<double>& target, std::string what);
// A whole number in [min, max].
TakeValue integerIn(long long& target, long long min, long long max, std::string what);
TakeValue integerIn(int& target, int min, int max, std::string what);
// A whole number (decimal digits) in [0, max]: seeds.
TakeValue unsignedUpTo(std::uint64_t& target, std::uint64_t max, std::string what);
TakeValue unsignedUpTo(std::optional<std::uint64_t>& target, std::uint64_t max, std::string what);
// A non-empty text ("a file name").
TakeValue text(std::string& target, std::string what);
TakeValue text(std::optional<std::string>& target, std::string what);
// A size "WxH" with both in [min, max] pixels.
TakeValue size(int& width, int& height, int min, int max);

template <std::size_t N>
bool readNumbers(std::string_view text, std::array<double, N>& out) {
  const std::vector<std::string> parts = splitList(text, ',');
  if (parts.size() != N) return false;
  for (std::size_t i = 0; i < N; ++i)
    if (!readNumber(parts[i], out[i])) return false;
  return true;
}

}  // namespace hemiroll::cli
