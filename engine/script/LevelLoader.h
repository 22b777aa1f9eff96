#pragma once
// Reads a level file (docs/LEVELS.md) into a LevelDef and a LevelScript: the
// level's reader on top of DataFileLoader. The file is Lua run in a fresh
// LuaSandbox (with `require` for scripts/ modules, the seeded
// hemiroll.random and the level API); it must return a plain table. Anything
// wrong with it — syntax, run-time error, quota, memory, a missing or
// mistyped field, an unknown key, a value out of range — throws ONE
// ScriptError whose message starts with "file:line:" (the line of the
// offending field as written in the file, found from the source text; the
// line of the returned table when the field is computed elsewhere).

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "engine/task/LevelDef.h"
#include "engine/script/TaskNames.h"
#include "engine/script/LevelScript.h"
#include "engine/script/SandboxLimits.h"

namespace hemiroll::script {

struct LevelLoadOptions {
  SandboxLimits limits;
  // Where require() finds modules; "" = defaultScriptsDir(level path) for
  // loadFile, and no modules for loadSource.
  std::string scriptsDir;
  std::uint64_t seed = 0;  // hemiroll.random's seed for this trial
  // Called with the level as its file declares it, before the level's script
  // is built from it: a research protocol's overrides (applyTrialOverrides),
  // so that the judge, the callbacks' state and the score all see them.
  std::function<void(LevelDef&)> adjust;
};

struct LoadedLevel {
  LevelDef def;
  std::shared_ptr<LevelScript> script;  // never null after a successful load
};

class LevelLoader {
 public:
  explicit LevelLoader(LevelLoadOptions options = {}) : options_(std::move(options)) {}

  LoadedLevel loadFile(const std::string& path) const;
  // The same from text in memory; `name` stands for the file in messages.
  LoadedLevel loadSource(std::string_view source, const std::string& name) const;

 private:
  LevelLoadOptions options_;
};

}  // namespace hemiroll::script
