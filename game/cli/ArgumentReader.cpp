#include "game/cli/ArgumentReader.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace hemiroll::cli {

ArgumentReader& ArgumentReader::flag(std::string name, std::function<void()> set) {
  entries_.push_back({std::move(name), std::move(set), {}});
  return *this;
}

ArgumentReader& ArgumentReader::option(std::string name, TakeValue take) {
  entries_.push_back({std::move(name), {}, std::move(take)});
  return *this;
}

ArgumentReader& ArgumentReader::positional(std::string what, std::size_t count,
                                           std::function<void(const std::string&)> take) {
  positionalWhat_ = std::move(what);
  positionalCount_ = count;
  takePositional_ = std::move(take);
  return *this;
}

const ArgumentReader::Entry* ArgumentReader::find(std::string_view name) const {
  for (const Entry& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

std::string ArgumentReader::read(const std::vector<std::string>& args) const {
  std::size_t positionals = 0;
  bool flagsEnded = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (!flagsEnded && arg == "--") {
      flagsEnded = true;
      continue;
    }
    if (flagsEnded || arg.empty() || arg[0] != '-' || arg == "-") {
      if (positionals == positionalCount_) {
        if (positionalCount_ == 0) return "unexpected argument '" + arg + "'";
        return "unexpected argument '" + arg + "' (only " + (positionalCount_ == 1 ? "one " : std::to_string(positionalCount_) + " ") +
               positionalWhat_ + (positionalCount_ == 1 ? "" : "s") + ")";
      }
      ++positionals;
      takePositional_(arg);
      continue;
    }
    const std::size_t eq = arg.find('=');
    const std::string name = arg.substr(0, eq);
    const Entry* entry = find(name);
    if (entry == nullptr) return "unknown flag '" + name + "'";
    if (entry->set) {
      if (eq != std::string::npos) return "flag " + name + " takes no value";
      entry->set();
      continue;
    }
    std::string value;
    if (eq != std::string::npos) {
      value = arg.substr(eq + 1);
    } else {
      if (i + 1 >= args.size()) return "flag " + name + " needs a value";
      value = args[++i];
    }
    if (std::string error = entry->take(name, value); !error.empty()) return error;
  }
  return "";
}

std::string needs(const std::string& flag, std::string_view what, const std::string& value) {
  return "flag " + flag + " needs " + std::string(what) + ", got '" + value + "'";
}

bool readNumber(std::string_view text, double& out) {
  // from_chars takes no leading '+'; a number written "+1" is still a number.
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return false;
  }
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(out);
}

bool readInteger(std::string_view text, long long& out) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return r.ec == std::errc() && r.ptr == end;
}

bool readUnsigned(std::string_view text, unsigned long long& out) {
  if (text.empty() || text.front() == '-') return false;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, out);
  return r.ec == std::errc() && r.ptr == end;
}

bool readSize(std::string_view text, int& width, int& height) {
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos) return false;
  long long w = 0, h = 0;
  if (!readInteger(text.substr(0, x), w) || !readInteger(text.substr(x + 1), h)) return false;
  if (w < 0 || h < 0 || w > std::numeric_limits<int>::max() || h > std::numeric_limits<int>::max()) return false;
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

std::vector<std::string> splitList(std::string_view text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = text.find(separator, start);
    parts.emplace_back(text.substr(start, at - start));
    if (at == std::string_view::npos) break;
    start = at + 1;
  }
  return parts;
}

namespace {

template <typename Store>
TakeValue numberInto(Store store, double min, double max, std::string what) {
  return [store = std::move(store), min, max, what = std::move(what)](const std::string& flag, const std::string& value) {
    double x = 0.0;
    if (!readNumber(value, x) || x < min || x > max) return needs(flag, what, value);
    store(x);
    return std::string();
  };
}

}  // namespace

TakeValue numberIn(double& target, double min, double max, std::string what) {
  return numberInto([&target](double x) { target = x; }, min, max, std::move(what));
}

TakeValue numberIn(std::optional<double>& target, double min, double max, std::string what) {
  return numberInto([&target](double x) { target = x; }, min, max, std::move(what));
}

TakeValue positiveNumber(double& target, std::string what) {
  return numberIn(target, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                  std::move(what));
}

TakeValue positiveNumber(std::optional<double>& target, std::string what) {
  return numberIn(target, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                  std::move(what));
}

TakeValue integerIn(long long& target, long long min, long long max, std::string what) {
  return [&target, min, max, what = std::move(what)](const std::string& flag, const std::string& value) {
    long long x = 0;
    if (!readInteger(value, x) || x < min || x > max) return needs(flag, what, value);
    target = x;
    return std::string();
  };
}

TakeValue integerIn(int& target, int min, int max, std::string what) {
  return [&target, min, max, what = std::move(what)](const std::string& flag, const std::string& value) {
    long long x = 0;
    if (!readInteger(value, x) || x < min || x > max) return needs(flag, what, value);
    target = static_cast<int>(x);
    return std::string();
  };
}

TakeValue unsignedUpTo(std::uint64_t& target, std::uint64_t max, std::string what) {
  return [&target, max, what = std::move(what)](const std::string& flag, const std::string& value) {
    unsigned long long x = 0;
    if (!readUnsigned(value, x) || x > max) return needs(flag, what, value);
    target = x;
    return std::string();
  };
}

TakeValue unsignedUpTo(std::optional<std::uint64_t>& target, std::uint64_t max, std::string what) {
  return [&target, max, what = std::move(what)](const std::string& flag, const std::string& value) {
    unsigned long long x = 0;
    if (!readUnsigned(value, x) || x > max) return needs(flag, what, value);
    target = x;
    return std::string();
  };
}

TakeValue text(std::string& target, std::string what) {
  return [&target, what = std::move(what)](const std::string& flag, const std::string& value) {
    if (value.empty()) return needs(flag, what, value);
    target = value;
    return std::string();
  };
}

TakeValue text(std::optional<std::string>& target, std::string what) {
  return [&target, what = std::move(what)](const std::string& flag, const std::string& value) {
    if (value.empty()) return needs(flag, what, value);
    target = value;
    return std::string();
  };
}

TakeValue size(int& width, int& height, int min, int max) {
  return [&width, &height, min, max](const std::string& flag, const std::string& value) {
    int w = 0, h = 0;
    if (!readSize(value, w, h) || w < min || h < min || w > max || h > max)
      return needs(flag, "WxH in pixels with both in " + std::to_string(min) + ".." + std::to_string(max), value);
    width = w;
    height = h;
    return std::string();
  };
}

}  // namespace hemiroll::cli
