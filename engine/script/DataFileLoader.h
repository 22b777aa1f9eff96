#pragma once
// The one loader of Lua data files: levels, research protocols, sweep specs
// and scenarios. It owns what they share: reading the file (size limit,
// byte-order mark, shebang line), running it in a fresh LuaSandbox under the
// quotas, checking that it returned a table, handing that table to the
// kind's reader, and turning every failure into ONE ScriptError that starts
// "file:line:". A reader says what is wrong as a FieldFailure {field,
// message} (LuaTableReader::fail); the line is that field's line as written,
// from LevelSourceMap. Anything else keeps the line Lua gave it.
//
// The loaders (LevelLoader, ProtocolLoader, SweepLoader, ScenarioLoader) are
// the kinds' readers on top of this.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "engine/script/LuaSandbox.h"
#include "engine/script/LuaTableReader.h"
#include "engine/script/SandboxLimits.h"

namespace hemiroll::script {

// What the messages call a kind of file and what its chunk returns.
struct DataFileKind {
  const char* file;   // "level file": "path:1: cannot open the level file"
  const char* table;  // "level": "lv.lua:1: the level must return a table, got number"
};

// The table the chunk returned, on top of the sandbox's stack. Functions in
// it live in `sandbox`: a reader that keeps one keeps the sandbox.
struct DataTable {
  const LuaTableReader& top;  // path ""
  const std::shared_ptr<LuaSandbox>& sandbox;
};

class DataFileLoader {
 public:
  // Installs what a kind's chunk may use beyond the sandbox's allow-list
  // (a level's require, random and API), before the chunk runs.
  using Prepare = std::function<void(LuaSandbox&)>;

  DataFileLoader(DataFileKind kind, const SandboxLimits& limits, Prepare prepare = {})
      : kind_(kind), limits_(limits), prepare_(std::move(prepare)) {}

  // The file's text (readScriptText); "path:1: ..." when it is missing,
  // unreadable, or larger than the memory limit (it could not be run).
  std::string readFile(const std::string& path) const;

  // Runs `source` (`name` stands for the file in messages) and returns what
  // read(const DataTable&) makes of the returned table.
  template <class Read>
  auto loadSource(std::string_view source, const std::string& name, Read&& read) const {
    std::optional<std::invoke_result_t<Read&, const DataTable&>> out;
    run(source, name, [&](const DataTable& table) { out.emplace(read(table)); });
    return std::move(*out);
  }
  template <class Read>
  auto loadFile(const std::string& path, Read&& read) const {
    return loadSource(readFile(path), path, std::forward<Read>(read));
  }

 private:
  void run(std::string_view source, const std::string& name, const std::function<void(const DataTable&)>& read) const;

  DataFileKind kind_;
  SandboxLimits limits_;
  Prepare prepare_;
};

}  // namespace hemiroll::script
