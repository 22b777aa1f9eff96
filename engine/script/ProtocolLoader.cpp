#include "engine/script/ProtocolLoader.h"

#include "engine/physics/ForceCoupling.h"

#include <lua.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <iterator>
#include <string>
#include <optional>
#include <vector>

#include "engine/script/DataFileLoader.h"
#include "engine/script/LevelFieldChecks.h"
#include "engine/script/LuaTableReader.h"

namespace hemiroll::script {

namespace fs = std::filesystem;

namespace {

// What messages call a protocol file and what its chunk returns.
constexpr DataFileKind kProtocolFile{"protocol file", "protocol"};

constexpr std::initializer_list<const char*> kMethods = {"M1", "M2", "M3", "visual"};
constexpr int kMaxRepetitions = 10000;
// A plan larger than this is a mistake (a loop gone wrong): 10 000 trials
// are weeks of sittings. It bounds what a session holds and writes for its
// plan: a manifest of about 0.8 kB a trial, parsed back at every resume
// (100 000 trials made a 77 MB manifest and 420-525 MB of memory; issue 33).
constexpr int kMaxTrials = 10000;

struct LevelFolders {
  std::string base;    // the protocol's folder
  std::string levels;  // the project's levels folder ("" = none)
};

std::string shown(const std::string& dir) { return dir.empty() ? "." : dir; }

// The level file as found, or "" when it is in neither folder.
std::string findLevel(const std::string& written, const LevelFolders& folders) {
  const fs::path path(written);
  std::vector<fs::path> candidates;
  if (path.is_absolute()) {
    candidates.push_back(path);
  } else {
    candidates.push_back(fs::path(folders.base) / path);
    if (!folders.levels.empty()) candidates.push_back(fs::path(folders.levels) / path);
  }
  std::error_code error;
  for (const fs::path& c : candidates)
    if (!written.empty() && fs::is_regular_file(c, error)) return c.lexically_normal().string();
  return "";
}

std::string resolveLevel(const LuaTableReader& table, const std::string& written, const LevelFolders& folders) {
  const std::string found = findLevel(written, folders);
  if (found.empty()) {
    std::string looked = shown(folders.base);
    if (!folders.levels.empty() && !fs::path(written).is_absolute()) looked += " and " + shown(folders.levels);
    table.fail("level", "no level file '" + written + "' (looked in " + looked + ")");
  }
  return found;
}

std::optional<double> readNonNegative(const LuaTableReader& table, const char* key, const char* unit) {
  const auto value = table.number(key);
  if (value && *value < 0.0) table.fail(key, std::string("must be >= 0 (") + unit + ")");
  return value;
}

double readFadeValue(const LuaTableReader& table, const char* key, double fallback) {
  const double v = table.number(key, fallback);
  if (v < 0.0 || v > 1.0) table.fail(key, "must be in [0, 1] (1 = full guidance, 0 = none)");
  return v;
}

// `name` when it is one of `allowed`; else fails naming the key, with the
// nearest allowed name or, when none is near, the list (`expected`).
std::string oneOf(const LuaTableReader& table, const char* key, const std::string& name,
                  std::initializer_list<const char*> allowed, const char* what, const char* expected) {
  if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return name == a; })) {
    const char* near = nearestName(name, allowed);
    table.fail(key, "unknown " + std::string(what) + " '" + name + "'" +
                        (near ? " (did you mean '" + std::string(near) + "'?)" : " (expected " + std::string(expected) + ")"));
  }
  return name;
}

// guidance = { kind = ..., stiffness | gain = ..., damping = ..., max_error = ..., fade = { ... } }
GuidanceSpec readGuidance(const LuaTableReader& table) {
  rejectUnknownLevelKeys(table, {"kind", "stiffness", "gain", "damping", "max_error", "fade"});
  GuidanceSpec g;
  const auto kind = table.string("kind");
  if (!kind) table.fail("kind", "missing; \"none\", \"autopilot\" or \"error_augmentation\"");
  g.kind = oneOf(table, "kind", *kind, {"none", "autopilot", "error_augmentation"}, "guidance kind",
                 "\"none\", \"autopilot\" or \"error_augmentation\"");
  // The spring's name says its sign: autopilot guidance has a stiffness
  // (towards the plan), error augmentation a gain (away from it).
  const char* spring = g.kind == "error_augmentation" ? "gain" : "stiffness";
  const char* other = g.kind == "error_augmentation" ? "stiffness" : "gain";
  if (table.typeOf(other) != LUA_TNIL)
    table.fail(other, std::string("not a key of ") + g.kind + " guidance (its spring is '" + spring + "')");
  const auto k = readNonNegative(table, spring, "N/m");
  if (g.kind != "none" && !k) table.fail(spring, "missing; the guidance spring [N/m]");
  g.stiffness = k.value_or(0.0);
  g.damping = readNonNegative(table, "damping", "N s/m").value_or(0.0);
  g.maxError = readPositive(table, "max_error", "m").value_or(g.maxError);
  // The bounds of every gain, wherever it is given (physics/ForceCoupling.h).
  if (g.stiffness > physics::kMaxStiffness) table.fail(spring, "must be at most 1e6 N/m");
  if (g.damping > physics::kMaxDamping) table.fail("damping", "must be at most 1e4 N s/m");
  if (g.maxError > physics::kMaxGuidanceError) table.fail("max_error", "must be at most 1 m");
  if (const auto fade = table.table("fade")) {
    rejectUnknownLevelKeys(*fade, {"from", "to", "over_trials"});
    g.fade.from = readFadeValue(*fade, "from", 1.0);
    g.fade.to = readFadeValue(*fade, "to", g.fade.from);
    g.fade.overTrials = readInteger(*fade, "over_trials", 1, kMaxRepetitions).value_or(1);
  }
  return g;
}

// The keys of a trial override, the ones readOverrides reads: the one list
// of them (a block's, a condition's and a group's change accept them all).
constexpr const char* kOverrideKeys[] = {"method", "kr", "kv", "alpha", "time_limit", "guidance"};

// A table's own keys, then the override keys, then `after`: the order a
// refusal lists them in.
std::vector<const char*> keysWithOverrides(std::initializer_list<const char*> own,
                                           std::initializer_list<const char*> after = {}) {
  std::vector<const char*> keys(own);
  keys.insert(keys.end(), std::begin(kOverrideKeys), std::end(kOverrideKeys));
  keys.insert(keys.end(), after);
  return keys;
}

// "method, kr, kv, alpha, time_limit or guidance"
std::string overrideKeysInWords() {
  std::string words;
  const std::size_t n = std::size(kOverrideKeys);
  for (std::size_t i = 0; i < n; ++i) words += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + std::string(kOverrideKeys[i]);
  return words;
}

// method, kr, kv, alpha, time_limit, guidance of a block or a condition.
TrialOverrides readOverrides(const LuaTableReader& table) {
  TrialOverrides o;
  if (const auto method = table.string("method"))
    o.method = oneOf(table, "method", *method, kMethods, "method", "\"M1\", \"M2\", \"M3\" or \"visual\"");
  o.stiffness = readNonNegative(table, "kr", "stiffness, N/m");
  o.damping = readNonNegative(table, "kv", "damping, N s/m");
  o.alpha = readPositive(table, "alpha", "the normal / in-face gain ratio");
  o.timeLimit = readPositive(table, "time_limit", "s");
  // A level's bounds (TaskDef.h, ForceCoupling.h): an override may not give
  // what the level itself could not (time_limit = 1e16 wrote 258 MB in 20 s).
  if (o.timeLimit && *o.timeLimit > kMaxTimeLimit)
    table.fail("time_limit", "must be at most " + std::to_string(static_cast<int>(kMaxTimeLimit)) +
                                 " s (a day), as a level's");
  if (const auto error = physics::couplingError(overriddenCoupling(o, physics::CouplingDef{})))
    table.fail(error->field, error->message);
  if (const auto guidance = table.table("guidance")) o.guidance = readGuidance(*guidance);
  return o;
}


// A list of tables under `key` (positions 1..n, nothing else), at least one.
int listLength(const LuaTableReader& list, const char* what) {
  const int count = list.entryCount();
  if (count == 0) list.fail("", std::string("empty; give at least one ") + what);
  if (static_cast<int>(lua_rawlen(list.state(), list.index())) != count)
    list.fail("", std::string("expected a list of ") + what + "s { ... }, { ... }");
  for (int i = 1; i <= count; ++i)
    if (list.typeAt(i) != LUA_TTABLE) list.fail(positionKey(i), std::string("expected a ") + what + " table { ... }");
  return count;
}

LuaTableReader entry(const LuaTableReader& list, int i) {
  lua_rawgeti(list.state(), list.index(), i);
  return LuaTableReader(list.state(), -1, list.source(), list.fieldPath(positionKey(i)));
}

ConditionDef readCondition(const LuaTableReader& table, const TrialOverrides& blockOverrides,
                           const std::optional<std::string>& blockLevel, const LuaTableReader& block,
                           const LevelFolders& folders) {
  rejectUnknownLevelKeys(table, keysWithOverrides({"label", "level"}));
  ConditionDef c;
  c.overrides = mergedOver(blockOverrides, readOverrides(table));  // the condition's over its block's
  const auto own = table.string("level");
  if (own) {
    c.level = *own;
    c.levelPath = resolveLevel(table, c.level, folders);
  } else if (blockLevel) {
    c.level = *blockLevel;
    c.levelPath = resolveLevel(block, c.level, folders);
  } else {
    table.fail("level", "missing; give the level file in the condition or in its block");
  }
  c.labelGiven = table.typeOf("label") != LUA_TNIL;
  c.label = table.string("label").value_or(defaultConditionLabel(c.overrides, c.level));
  if (c.label.empty()) table.fail("label", "must not be empty");
  return c;
}

BreakDef readBreak(const LuaTableReader& table) {
  rejectUnknownLevelKeys(table, {"message", "min_duration", "stop"});
  BreakDef b;
  b.message = table.string("message").value_or("");
  b.minDuration = readNonNegative(table, "min_duration", "s").value_or(0.0);
  b.stop = readBool(table, "stop").value_or(false);
  return b;
}

BlockDef readBlock(const LuaTableReader& block, int index, const LevelFolders& folders) {
  rejectUnknownLevelKeys(block, keysWithOverrides({"name", "instructions", "label", "level", "conditions"},
                                                  {"repetitions", "randomise", "break_after"}));
  BlockDef b;
  b.name = block.string("name").value_or("block " + std::to_string(index));
  if (b.name.empty()) block.fail("name", "must not be empty");
  b.instructions = block.string("instructions").value_or("");
  const TrialOverrides overrides = readOverrides(block);
  const auto level = block.string("level");
  if (const auto list = block.table("conditions")) {
    if (block.typeOf("label") != LUA_TNIL)
      block.fail("label", "a block with conditions has no label of its own: label each condition");
    const int count = listLength(*list, "condition");
    for (int i = 1; i <= count; ++i)
      b.conditions.push_back(readCondition(entry(*list, i), overrides, level, block, folders));
  } else {
    if (!level) block.fail("level", "missing; every block needs a level file (or conditions that each name one)");
    ConditionDef c;
    c.level = *level;
    c.levelPath = resolveLevel(block, c.level, folders);
    c.overrides = overrides;
    c.labelGiven = block.typeOf("label") != LUA_TNIL;
    c.label = block.string("label").value_or(defaultConditionLabel(c.overrides, c.level));
    if (c.label.empty()) block.fail("label", "must not be empty");
    b.conditions.push_back(std::move(c));
  }
  b.repetitions = readInteger(block, "repetitions", 1, kMaxRepetitions).value_or(1);
  b.randomise = readBool(block, "randomise").value_or(false);
  if (const auto pause = block.table("break_after")) b.breakAfter = readBreak(*pause);
  return b;
}


// The 0-based block named `name`, or fails naming the blocks there are.
int blockNamed(const LuaTableReader& table, const char* key, const std::string& name, const ProtocolDef& def) {
  for (std::size_t b = 0; b < def.blocks.size(); ++b)
    if (def.blocks[b].name == name) return static_cast<int>(b);
  std::string names;
  for (const BlockDef& b : def.blocks) names += (names.empty() ? "'" : ", '") + b.name + "'";
  table.fail(key, "no block named '" + name + "' (the blocks: " + names + ")");
}

// groups = { { name = ..., description = ..., changes = { { block = NAME, <overrides> }, ... } }, ... }
std::vector<GroupDef> readGroups(const LuaTableReader& list, const ProtocolDef& def) {
  std::vector<GroupDef> groups;
  const int count = listLength(list, "group");
  for (int i = 1; i <= count; ++i) {
    const LuaTableReader table = entry(list, i);
    rejectUnknownLevelKeys(table, {"name", "description", "changes"});
    GroupDef g;
    const auto name = table.string("name");
    if (!name) table.fail("name", "missing; every group needs a name (it names the group in results)");
    if (!isFolderName(*name))
      table.fail("name", "'" + *name + "' is not a group name: use 1 to 64 letters, digits, '-' or '_'");
    const auto lower = [](std::string text) {
      for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return text;
    };
    for (const GroupDef& other : groups) {
      if (other.name == *name) table.fail("name", "'" + *name + "' names two groups");
      if (lower(other.name) == lower(*name))
        table.fail("name", "'" + *name + "' and '" + other.name + "' differ only in case; name groups apart");
    }
    g.name = *name;
    g.description = table.string("description").value_or("");
    if (const auto changes = table.table("changes")) {
      const int n = listLength(*changes, "change");
      for (int k = 1; k <= n; ++k) {
        const LuaTableReader change = entry(*changes, k);
        rejectUnknownLevelKeys(change, keysWithOverrides({"block"}));
        const auto block = change.string("block");
        if (!block) change.fail("block", "missing; the name of the block this change applies to");
        GroupChange c;
        c.block = blockNamed(change, "block", *block, def);
        for (const GroupChange& earlier : g.changes)
          if (earlier.block == c.block)
            change.fail("block", "'" + *block + "' is changed twice in group '" + g.name +
                                     "'; put everything the group changes in that block into one change");
        c.overrides = readOverrides(change);
        if (c.overrides.empty()) change.fail("", "changes nothing; give " + overrideKeysInWords());
        g.changes.push_back(std::move(c));
      }
    }
    groups.push_back(std::move(g));
  }
  return groups;
}

// counterbalance = { "block a", "block b", ... }: at least two blocks, each once.
std::vector<int> readCounterbalance(const LuaTableReader& list, const ProtocolDef& def) {
  lua_State* L = list.state();
  const int count = list.entryCount();
  if (count < 2 || static_cast<int>(lua_rawlen(L, list.index())) != count)
    list.fail("", "expected a list of at least two block names { \"a\", \"b\" }");
  std::vector<int> blocks;
  for (int i = 1; i <= count; ++i) {
    lua_rawgeti(L, list.index(), i);
    const bool isText = lua_type(L, -1) == LUA_TSTRING;
    const std::string name = isText ? lua_tostring(L, -1) : "";
    lua_pop(L, 1);
    if (!isText) list.fail(positionKey(i), "expected a block name (a string)");
    const int b = blockNamed(list, positionKey(i).c_str(), name, def);
    if (std::find(blocks.begin(), blocks.end(), b) != blocks.end())
      list.fail(positionKey(i), "'" + name + "' is listed twice");
    blocks.push_back(b);
  }
  std::sort(blocks.begin(), blocks.end());  // their places, in file order
  return blocks;
}

// A Lua integer, or a float with a whole value (1e3), from 0 to 2^63 - 1.
std::uint64_t readSeed(const LuaTableReader& top) {
  lua_State* L = top.state();
  top.pushField("seed");
  const int type = lua_type(L, -1);
  const std::string got = describeLuaValue(L, -1);
  std::optional<lua_Integer> value;
  if (lua_isinteger(L, -1)) {
    value = lua_tointeger(L, -1);
  } else if (type == LUA_TNUMBER) {
    const double d = lua_tonumber(L, -1);
    if (d == std::floor(d) && std::fabs(d) < 9.2e18) value = static_cast<lua_Integer>(d);
  }
  lua_pop(L, 1);
  if (type == LUA_TNIL) return 0;
  if (!value || *value < 0) top.fail("seed", "expected a whole number from 0 to 9223372036854775807, got " + got);
  return static_cast<std::uint64_t>(*value);
}

ProtocolDef readProtocol(const LuaTableReader& top, const LevelFolders& folders) {
  rejectUnknownLevelKeys(top, {"experiment", "description", "version", "seed", "device_profile", "blocks", "groups",
                               "assignment", "participants", "counterbalance"});
  ProtocolDef def;
  def.source = top.source();
  const auto experiment = top.string("experiment");
  if (!experiment) top.fail("experiment", "missing; every protocol needs an experiment id (a string)");
  if (!isFolderName(*experiment))
    top.fail("experiment", "'" + *experiment + "' is not a folder name: use 1 to 64 letters, digits, '-' or '_'");
  def.experiment = *experiment;
  def.description = top.string("description").value_or("");
  def.version = top.string("version").value_or(def.version);
  def.seed = readSeed(top);
  def.deviceProfile = top.string("device_profile").value_or("");
  if (top.typeOf("device_profile") != LUA_TNIL && def.deviceProfile.empty())
    top.fail("device_profile", "must name a device profile (\"touch\", \"omega3\", ...), not be empty");
  const auto blocks = top.table("blocks");
  if (!blocks) top.fail("blocks", "missing; a protocol is a list of blocks { {level = ...}, ... }");
  const int count = listLength(*blocks, "block");
  long long trials = 0;
  for (int i = 1; i <= count; ++i) {
    const LuaTableReader block = entry(*blocks, i);
    def.blocks.push_back(readBlock(block, i, folders));
    const BlockDef& b = def.blocks.back();
    trials += static_cast<long long>(b.conditions.size()) * b.repetitions;
    if (trials > kMaxTrials)
      block.fail("repetitions", "the plan would exceed " + std::to_string(kMaxTrials) + " trials");
    if (i == count && b.breakAfter)
      block.fail("break_after", "the last block has no block after it (a break goes between blocks)");
  }
  // Groups and counterbalancing name blocks: a name two blocks share would
  // quietly mean the first.
  if (top.table("groups") || top.table("counterbalance"))
    for (std::size_t i = 0; i < def.blocks.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (def.blocks[i].name == def.blocks[j].name)
          entry(*blocks, static_cast<int>(i) + 1)
              .fail("name", "'" + def.blocks[i].name + "' names blocks " + std::to_string(j + 1) + " and " +
                                std::to_string(i + 1) + "; groups and counterbalance name blocks, so each needs its own");
  if (const auto groups = top.table("groups")) def.groups = readGroups(*groups, def);
  if (const auto counterbalance = top.table("counterbalance")) def.counterbalanced = readCounterbalance(*counterbalance, def);
  if (const auto participants = top.string("participants")) {
    std::error_code error;
    const fs::path written(*participants);
    const fs::path found = written.is_absolute() ? written : fs::path(folders.base) / written;
    if (participants->empty() || !fs::is_regular_file(found, error))
      top.fail("participants", "no participants file '" + *participants + "' (looked in " + shown(folders.base) + ")");
    def.participantsFile = found.lexically_normal().string();
  }
  if (const auto assignment = top.string("assignment")) {
    oneOf(top, "assignment", *assignment, {"balanced", "participants_file"}, "assignment",
          "\"balanced\" or \"participants_file\"");
    def.assignment = *assignment == "balanced" ? Assignment::Balanced : Assignment::ParticipantsFile;
  }
  if (def.assignment == Assignment::ParticipantsFile && def.participantsFile.empty())
    top.fail("assignment", "\"participants_file\" needs the participants file: participants = \"participants.tsv\"");
  if (def.assignment == Assignment::ParticipantsFile && def.groups.empty())
    top.fail("assignment", "\"participants_file\" assigns groups, and the protocol has none (groups = { ... })");
  return def;
}

// A protocol is data: its sandbox has no require and no random (the engine
// shuffles, ProtocolPlan).
DataFileLoader protocolFileLoader(const SandboxLimits& limits) { return DataFileLoader(kProtocolFile, limits); }

}  // namespace

std::string ProtocolLoader::levelsDirFor(const std::string& path) const {
  if (!options_.levelsDir.empty()) return options_.levelsDir;
  for (const fs::path& start : {fs::path(path), fs::absolute(path)})
    for (fs::path dir = start.parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path())
      if (dir.filename() == "levels") return dir.string();
  return "";
}

ProtocolDef ProtocolLoader::loadFile(const std::string& path) const {
  return protocolFileLoader(options_.limits).loadFile(path, [&](const DataTable& data) {
    return readProtocol(data.top, {fs::path(path).parent_path().string(), levelsDirFor(path)});
  });
}

ProtocolDef ProtocolLoader::loadSource(std::string_view source, const std::string& name,
                                       const std::string& baseDir) const {
  return protocolFileLoader(options_.limits).loadSource(source, name, [&](const DataTable& data) {
    return readProtocol(data.top, {baseDir, options_.levelsDir});
  });
}

}  // namespace hemiroll::script
