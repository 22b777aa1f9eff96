#include "game/research/sweep/SbatchDirectives.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace hemiroll::game {

namespace {

bool allDigits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::vector<std::string_view> split(std::string_view s, char at) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = s.find(at, start);
    parts.push_back(s.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// sbatch's one-letter options, by their long names (man sbatch).
std::string longOption(char letter) {
  static const std::map<char, std::string> names = {
      {'A', "account"}, {'a', "array"},     {'C', "constraint"}, {'c', "cpus-per-task"}, {'D', "chdir"},
      {'d', "dependency"}, {'e', "error"},  {'G', "gpus"},       {'H', "hold"},          {'i', "input"},
      {'J', "job-name"}, {'k', "no-kill"},  {'L', "licenses"},   {'M', "clusters"},      {'m', "distribution"},
      {'N', "nodes"},   {'n', "ntasks"},    {'o', "output"},     {'p', "partition"},     {'q', "qos"},
      {'s', "oversubscribe"}, {'t', "time"}, {'W', "wait"},      {'w', "nodelist"},      {'x', "exclude"}};
  const auto it = names.find(letter);
  return it == names.end() ? std::string("-") + letter : it->second;
}

}  // namespace

std::optional<std::string> slurmTimeProblem(std::string_view value) {
  const std::string wanted =
      "a time limit as Slurm writes it: minutes, M:S, H:M:S, D-H, D-H:M or D-H:M:S (e.g. 90 or 1-12:00:00)";
  if (value == "UNLIMITED" || value == "INFINITE") return std::nullopt;
  const std::size_t dash = value.find('-');
  const std::string_view days = dash == std::string_view::npos ? std::string_view() : value.substr(0, dash);
  const std::string_view clock = dash == std::string_view::npos ? value : value.substr(dash + 1);
  if (dash != std::string_view::npos && !allDigits(days)) return wanted;
  const std::vector<std::string_view> fields = split(clock, ':');
  if (fields.size() > 3 || !std::all_of(fields.begin(), fields.end(), allDigits)) return wanted;
  // Every field after the first is a clock's: under 60 (under 24 for the
  // hours after days), and not so long that it stops being a number.
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].size() > 9) return wanted;
    const bool hoursAfterDays = dash != std::string_view::npos && i == 0;
    const bool later = i > 0;
    if ((later || hoursAfterDays) && std::stol(std::string(fields[i])) >= (hoursAfterDays ? 24 : 60)) return wanted;
  }
  if (days.size() > 5) return wanted;
  const bool anyNonzero = std::any_of(fields.begin(), fields.end(), [](std::string_view f) {
    return f.find_first_not_of('0') != std::string_view::npos;
  }) || days.find_first_not_of('0') != std::string_view::npos;
  // Slurm reads a zero limit as "no limit": the opposite of what was asked.
  if (!anyNonzero) return "a time limit above zero (Slurm reads 0 as no limit at all)";
  return std::nullopt;
}

std::optional<std::string> slurmNameProblem(std::string_view value) {
  const bool good = !value.empty() && std::all_of(value.begin(), value.end(), [](unsigned char c) {
    return std::isalnum(c) != 0 || c == '_' || c == '-' || c == '.' || c == ',';
  });
  const std::vector<std::string_view> items = split(value, ',');
  if (!good || std::any_of(items.begin(), items.end(), [](std::string_view item) { return item.empty(); }))
    return "a name of letters, digits, '_', '-', '.' (a list joined by ',', none empty)";
  return std::nullopt;
}

std::optional<std::string> slurmMemoryProblem(std::string_view value) {
  std::string_view digits = value;
  if (!digits.empty() && std::string_view("KMGTkmgt").find(digits.back()) != std::string_view::npos)
    digits.remove_suffix(1);
  // 0 is Slurm's "all the node's memory", a request sites allow; past 12
  // digits a number is a typing slip, not memory.
  if (!allDigits(digits) || digits.size() > 12)
    return "memory per node as Slurm writes it: a whole number with an optional unit K, M, G or T (e.g. 4G)";
  return std::nullopt;
}

std::string sbatchPathValue(std::string_view folder, std::string_view pattern) {
  std::string out = "\"";
  for (const char c : folder) {
    if (c == '%') out += "%%";
    else if (c == '"') out += "\\\"";
    else out += c;
  }
  return out + "/" + std::string(pattern) + "\"";
}

std::string sbatchOption(std::string_view line) {
  line = trimmed(line);
  constexpr std::string_view kTag = "#SBATCH";
  if (line.substr(0, kTag.size()) != kTag || line.size() == kTag.size() ||
      !std::isspace(static_cast<unsigned char>(line[kTag.size()])))
    return {};
  const std::string_view option = trimmed(line.substr(kTag.size()));
  if (option.substr(0, 2) == "--") return std::string(option.substr(2, option.find_first_of("= \t") - 2));
  if (option.size() >= 2 && option[0] == '-') return longOption(option[1]);
  return {};
}

namespace {
constexpr std::string_view kWrittenTag = "# hemiroll wrote the #SBATCH options:";

// The options previous's writtenOptionsLine names.
std::vector<std::string> optionsHemirollWrote(std::string_view previous) {
  std::vector<std::string> written;
  for (const std::string_view raw : split(previous, '\n')) {
    const std::string_view line = trimmed(raw);
    if (line.substr(0, kWrittenTag.size()) != kWrittenTag) continue;
    for (std::string_view word : split(line.substr(kWrittenTag.size()), ' '))
      if (!(word = trimmed(word)).empty()) written.emplace_back(word);
  }
  return written;
}
}  // namespace

std::string writtenOptionsLine(std::string_view fileText) {
  std::string line(kWrittenTag);
  bool inHeader = true;
  for (const std::string_view raw : split(fileText, '\n')) {
    const std::string_view trimmedLine = trimmed(raw);
    if (!trimmedLine.empty() && trimmedLine.front() != '#') inHeader = false;
    if (!inHeader) break;
    if (const std::string option = sbatchOption(trimmedLine); !option.empty()) line += " " + option;
  }
  return line;
}

CarriedDirectives carryHandAddedDirectives(std::string_view previous, std::string_view fresh) {
  const std::vector<std::string> hemirollWrote = optionsHemirollWrote(previous);
  std::map<std::string, std::string> freshLines;  // option -> its line in fresh
  std::vector<std::string> freshAll;
  std::size_t insertAt = 0;  // after fresh's last #SBATCH line
  for (std::size_t start = 0; start < fresh.size();) {
    const std::size_t end = std::min(fresh.find('\n', start), fresh.size());
    const std::string_view line = fresh.substr(start, end - start);
    freshAll.emplace_back(trimmed(line));
    if (const std::string option = sbatchOption(line); !option.empty()) {
      freshLines.emplace(option, std::string(trimmed(line)));
      insertAt = std::min(end + 1, fresh.size());
    }
    start = end + 1;
  }

  CarriedDirectives carried;
  bool inHeader = true;  // sbatch reads #SBATCH lines up to the first command
  for (const std::string_view raw : split(previous, '\n')) {
    const std::string_view line = trimmed(raw);
    if (line.empty()) continue;
    const bool comment = line.front() == '#';
    if (!comment) inHeader = false;
    const std::string option = inHeader ? sbatchOption(line) : std::string();
    if (!option.empty()) {
      const auto same = freshLines.find(option);
      if (same == freshLines.end()) {
        if (std::find(hemirollWrote.begin(), hemirollWrote.end(), option) != hemirollWrote.end())
          carried.retired.emplace_back(line);
        else
          carried.kept.emplace_back(line);
      }
      else if (same->second != line) carried.replaced.emplace_back(line);
    } else if (!comment && std::find(freshAll.begin(), freshAll.end(), line) == freshAll.end()) {
      carried.dropped.emplace_back(line);
    }
  }
  carried.text = std::string(fresh);
  if (!carried.kept.empty()) {
    std::string block = "# Kept from the previous file (hemiroll does not write these):\n";
    for (const std::string& line : carried.kept) block += line + "\n";
    carried.text.insert(insertAt, block);
  }
  return carried;
}

}  // namespace hemiroll::game
