#pragma once
// A research protocol as its file declares it (docs/PROTOCOLS.md), in plain
// C++: an experiment of blocks, each block a list of conditions (a level and
// what the protocol overrides in it) run `repetitions` times, in order or
// shuffled, with an optional break after it. ProtocolLoader fills it;
// ProtocolPlan expands it into the flat list of trials a session runs.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/task/LevelDef.h"

namespace hemiroll::task {

// Haptic guidance of a condition (docs/PROTOCOLS.md "Guidance"): the kind
// and its gains as the protocol writes them, and how it fades over the
// block's trials. The game turns it into haptics::GuidanceDef.
struct GuidanceFade {
  double from = 1.0;    // the fade value of the block's first trial, [0, 1]
  double to = 1.0;      // ... of trial over_trials and every one after, [0, 1]
  int overTrials = 1;   // >= 1
};

struct GuidanceSpec {
  std::string kind = "none";  // "none", "autopilot" or "error_augmentation"
  double stiffness = 0.0;     // [N/m]: autopilot's `stiffness`, error augmentation's `gain`
  double damping = 0.0;       // [N s/m]
  double maxError = 0.02;     // [m] the spring's reach
  GuidanceFade fade;

  // The fade value of the block's trial `trialInBlock` (1-based): linear
  // from `from` at trial 1 to `to` at trial over_trials, then held.
  double fadeAt(int trialInBlock) const;
};

// What a protocol may change in a level for a trial. Unset = the level's.
struct TrialOverrides {
  std::optional<std::string> method;  // "M1", "M2", "M3" or "visual" (as a level's force.method)
  std::optional<double> stiffness;    // kr [N/m], >= 0
  std::optional<double> damping;      // kv [N s/m], >= 0
  std::optional<double> alpha;        // M3's normal / in-face gain ratio [-], > 0
  std::optional<double> timeLimit;    // [s], > 0
  std::optional<GuidanceSpec> guidance;  // unset = none

  bool empty() const { return !method && !stiffness && !damping && !alpha && !timeLimit && !guidance; }
};

// The coupling a level gets under the overrides: the method replaces the
// level's ("visual" = M3 gains, no rendered force, as in a level file), the
// gains replace the level's where given.
physics::CouplingDef overriddenCoupling(const TrialOverrides& overrides, const physics::CouplingDef& level);
// The coupling as above and the time limit, applied to a loaded level.
void applyTrialOverrides(const TrialOverrides& overrides, LevelDef& level);
// "M1", "M2", "M3" or "visual": the name a level file and a protocol use.
std::string couplingMethodName(const physics::CouplingDef& coupling);

// One condition of a block: a level with its overrides (the block's values
// merged in; the condition's own win).
struct ConditionDef {
  std::string label;      // names the condition in results ("M3 alpha 1.5"); default built from the overrides
  bool labelGiven = false;  // the file wrote the label (a group's changes then keep it)
  std::string level;      // the level file as the protocol writes it
  std::string levelPath;  // where the loader found it (relative to the working directory, or absolute)
  TrialOverrides overrides;
};

// Shown between this block and the next.
struct BreakDef {
  std::string message;
  double minDuration = 0.0;  // [s] before the next block may start (people; bots do not rest)
  // The sitting ends here: the session stops and running it again (same
  // participant and session) continues with the next block, e.g. the next day.
  bool stop = false;
};

struct BlockDef {
  std::string name;           // default "block N"
  std::string instructions;   // shown before the block's first trial
  std::vector<ConditionDef> conditions;  // at least one
  int repetitions = 1;        // passes through the conditions, >= 1
  bool randomise = false;     // shuffle the block's trials (all passes together)
  std::optional<BreakDef> breakAfter;  // never on the last block
};

// 1 to 64 letters, digits, '-' or '_': an id that may name a folder (the
// experiment's; the session's participant and session ids follow the same rule).
bool isFolderName(const std::string& id);

// A group of a between-subjects design (docs/PROTOCOLS.md "Groups"): what
// it changes in named blocks. Its values win over the block's and its
// conditions' for every trial of the block.
struct GroupChange {
  int block = 0;             // 0-based index into ProtocolDef::blocks
  TrialOverrides overrides;
};

struct GroupDef {
  std::string name;          // a folder-name-like id: names the group in results
  std::string description;
  std::vector<GroupChange> changes;
};

// How a new participant gets a group and a block order.
enum class Assignment {
  Balanced,          // by the order participants arrive (the k-th: group k mod G, order (k div G) mod R)
  ParticipantsFile,  // the participants file's `group` (and `order`) columns
};

// `own`'s values where it has them, `base`'s elsewhere: a condition's over
// its block's, a group's change over the condition's.
TrialOverrides mergedOver(const TrialOverrides& base, const TrialOverrides& own);
// The condition `condition` of `block` as `group` plays it (nullptr: no
// group): the group's changes to that block merged over it, and the
// default label rebuilt from the merged overrides unless the file gave one.
ConditionDef conditionInGroup(const ConditionDef& condition, int block, const GroupDef* group);
// The label a condition gets when its file gives none.
std::string defaultConditionLabel(const TrialOverrides& overrides, const std::string& level);

// Rows of a balanced Latin square (Williams 1949) over n items: every item
// in every position once, and every item immediately followed by every
// other once (n rows for an even n; for an odd n, 2n rows: the square and
// its mirror). Each row is a permutation of 0..n-1.
std::vector<std::vector<int>> williamsSquare(int n);

struct ProtocolDef {
  std::string source;       // the file as named by the caller, for messages
  std::string experiment;   // required; names the data folder: letters, digits, '-', '_'
  std::string description;
  std::string version = "1";
  std::uint64_t seed = 0;   // the randomisation's seed when the session gives none
  // The device the study is run on, by profile name (devices/NAME.lua;
  // docs/UDP_BRIDGE.md "Device profiles"); "" = none named.
  std::string deviceProfile;
  std::vector<BlockDef> blocks;  // at least one
  // Between-subjects design (all optional).
  std::vector<GroupDef> groups;            // empty: one group, unnamed
  Assignment assignment = Assignment::Balanced;
  std::string participantsFile;            // as found ("" = none); required for Assignment::ParticipantsFile
  std::vector<int> counterbalanced;        // 0-based blocks whose order is counterbalanced, in file order

  // Block orders a participant can get: the Williams square's rows over the
  // counterbalanced blocks (1 when none).
  int orderCount() const;
  // The blocks in the order participant order `order` (1-based) plays them,
  // as 0-based indices: the counterbalanced blocks permuted among their own
  // places, every other block where it is.
  std::vector<int> blockSequence(int order) const;
  // nullptr when `name` is no group's.
  const GroupDef* group(const std::string& name) const;
};

}  // namespace hemiroll::task
