#pragma once
// A simulated participant's memory across the trials of a session
// (docs/PROTOCOLS.md "Simulated participants"): a few named numbers a
// built-in bot keeps from one trial to the next (the human model: how many
// trials it has practised). Capped, so that what a session folder holds for
// it stays small: at most kMaxEntries names of 1 to kMaxNameLength
// characters (a-z, 0-9, '_'), each a finite number. The session writes it
// to the session folder after every trial (bot-memory.json) and a resumed
// session restores it.

#include <map>
#include <optional>
#include <string>

namespace hemiroll::script {

class BotMemory {
 public:
  static constexpr std::size_t kMaxEntries = 32;
  static constexpr std::size_t kMaxNameLength = 32;

  std::optional<double> get(const std::string& name) const;
  // Throws ScriptError for a bad name, a non-finite value, or a new name
  // beyond the cap.
  void set(const std::string& name, double value);
  const std::map<std::string, double>& entries() const { return entries_; }
  bool empty() const { return entries_.empty(); }

  // "" when `name` may name an entry; else why not.
  static std::string nameProblem(const std::string& name);

 private:
  std::map<std::string, double> entries_;
};

// The trial's place in a research session, for a bot's init (BotLevelInfo).
struct TrialPlace {
  bool inSession = false;     // false outside a session (run, the window's watch mode): the rest is unset
  int trialIndex = 0;         // 1-based, in the session
  int block = 0;              // 1-based place of its block
  std::string blockName;
  int trialInBlock = 0;
  int condition = 0;          // 1-based, in the block
  std::string conditionLabel;
  std::string group;          // "" without groups
  std::string guidance = "none";  // "none", "autopilot" or "error_augmentation"
  double guidanceFade = 0.0;  // the trial's fade value (0 without guidance)
};

}  // namespace hemiroll::script
