#pragma once
// Reads a research protocol file (docs/PROTOCOLS.md) into a ProtocolDef: the
// protocol's reader on top of DataFileLoader. The file is Lua run in a fresh
// LuaSandbox (no require, no hemiroll.random: a protocol is data; the engine
// shuffles, ProtocolPlan) and must return a plain table. Anything wrong with
// it - syntax, run-time error, quota, an unknown key (with the nearest
// allowed name), a wrong type, a value out of range, a level file that does
// not exist - throws ONE ScriptError "file:line: path: what", as LevelLoader
// does.
//
// Level files are looked for relative to the protocol file's folder first,
// then in the levels folder (ProtocolLoadOptions::levelsDir). The loader
// only checks that they exist; loading them is the session's business.

#include <string>
#include <string_view>

#include "engine/task/ProtocolDef.h"
#include "engine/script/TaskNames.h"
#include "engine/script/SandboxLimits.h"

namespace hemiroll::script {

struct ProtocolLoadOptions {
  SandboxLimits limits;
  // The project's levels folder; "" = the nearest folder named "levels" that
  // holds the protocol file (levels/protocols/x.lua -> levels/), if any.
  std::string levelsDir;
};

class ProtocolLoader {
 public:
  explicit ProtocolLoader(ProtocolLoadOptions options = {}) : options_(std::move(options)) {}

  ProtocolDef loadFile(const std::string& path) const;
  // The same from text; `name` stands for the file in messages, and level
  // files are looked for relative to `baseDir` (then levelsDir).
  ProtocolDef loadSource(std::string_view source, const std::string& name, const std::string& baseDir) const;

  // The levels folder loadFile uses for `path` (see levelsDir).
  std::string levelsDirFor(const std::string& path) const;

 private:
  ProtocolLoadOptions options_;
};

}  // namespace hemiroll::script
