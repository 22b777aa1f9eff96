#include "engine/script/BotMemory.h"

#include <cmath>

#include "engine/script/ScriptError.h"

namespace hemiroll::script {

std::optional<double> BotMemory::get(const std::string& name) const {
  const auto found = entries_.find(name);
  if (found == entries_.end()) return std::nullopt;
  return found->second;
}

std::string BotMemory::nameProblem(const std::string& name) {
  if (name.empty() || name.size() > kMaxNameLength)
    return "a memory entry's name has 1 to " + std::to_string(kMaxNameLength) + " characters";
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'))
      return "a memory entry's name is made of a-z, 0-9 and '_' ('" + name + "' is not)";
  return "";
}

void BotMemory::set(const std::string& name, double value) {
  if (const std::string problem = nameProblem(name); !problem.empty()) throw ScriptError("bot memory: " + problem);
  if (!std::isfinite(value)) throw ScriptError("bot memory: '" + name + "' must be a finite number");
  if (!entries_.count(name) && entries_.size() >= kMaxEntries)
    throw ScriptError("bot memory: at most " + std::to_string(kMaxEntries) + " entries (adding '" + name + "')");
  entries_[name] = value;
}

}  // namespace hemiroll::script
