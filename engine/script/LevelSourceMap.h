#pragma once
// Finds the line where a field of a returned data table is written, from the
// Lua source text alone, so that data errors can say "file:line:" although
// Lua tables keep no line numbers. It is the one source map: DataFileLoader
// asks it for every kind of data file (levels, protocols, sweep specs,
// scenarios); the name is from when levels were the only kind.
//
// Why not the compiled chunk's debug information: Lua keeps a line per VM
// instruction, not per table key, and the C API shows only a function's
// lines (linedefined, currentline, activelines). Mapping keys to lines from
// it would mean decoding lua_dump's version-specific bytecode, and list
// entries are stored in batches (one SETLIST for up to 50 of them), so their
// lines are not there at all.
//
// How: a small Lua tokenizer (comments, short and long strings, numbers,
// names, operators; block keywords counted so that statements inside
// function bodies are not taken for fields) finds every table constructor
// and its fields (name = v, ["s"] = v, [n] = v, positional). The root is the
// constructor after the chunk's last top-level `return`, or the one assigned
// to the name it returns (`local level = {...} ... return level`).
// lineOf("task.stages[2].hold") walks that tree; where the walk stops (the
// field was computed, or is absent) it answers the line of the deepest field
// found, the root's line, or the `return` line, in that order. It never
// fails: a file the tokenizer does not understand still gets line 1.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hemiroll::script {

class LevelSourceMap {
 public:
  explicit LevelSourceMap(std::string_view source);
  ~LevelSourceMap();
  LevelSourceMap(LevelSourceMap&&) noexcept;
  LevelSourceMap& operator=(LevelSourceMap&&) noexcept;

  // `path` as LuaTableReader writes it: names joined by '.', positions as
  // "[n]" ("" = the root table).
  int lineOf(std::string_view path) const;

  struct Constructor;  // internal

 private:
  std::vector<std::unique_ptr<Constructor>> constructors_;
  const Constructor* root_ = nullptr;
  int fallbackLine_ = 1;
};

}  // namespace hemiroll::script
