#pragma once
// Typed, path-aware reads of a plain Lua table that a script returned, for
// turning script data into C++ definition structs. Every failure throws a
// FieldFailure (a ScriptError) that names the file and the field path:
//   "rose.lua: drive.r1: expected a number, got string",
// and carries the field and the message apart for DataFileLoader.
//
// Reads are raw (no metamethods run), so reading data never executes script
// code: data tables are plain tables. Call only outside protected calls, on
// a LuaSandbox that is not running a script (the memory cap is then off, so
// no read can raise a Lua error).

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

struct lua_State;

namespace hemiroll::script {

class LuaTableReader {
 public:
  // Reads the table at stack index `index` of L (made absolute). `source`
  // names the file; `path` is the table's place in the data ("" at the top,
  // "drive", "drive.proxy").
  LuaTableReader(lua_State* L, int index, std::string source, std::string path);

  lua_State* state() const { return L_; }
  int index() const { return index_; }
  const std::string& source() const { return source_; }
  const std::string& path() const { return path_; }

  // "drive.r1" for key "r1" of table "drive"; "r1" at the top.
  std::string fieldPath(std::string_view key) const;
  // Throws FieldFailure {path.key, message}: "source: path.key: message"
  // ("source: path: message" for an empty key).
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

  // Lua type of the field (LUA_TNIL when absent).
  int typeOf(const char* key) const;
  int typeAt(long long position) const;

  // Absent -> nullopt; present but not a finite number -> throws.
  std::optional<double> number(const char* key) const;
  double number(const char* key, double fallback) const { return number(key).value_or(fallback); }
  std::optional<double> numberAt(long long position) const;
  std::optional<std::string> string(const char* key) const;

  // Pushes the field onto the stack (raw read). The caller pops it.
  void pushField(const char* key) const;

  // Pushes the sub-table onto the stack and returns its reader; nullopt (and
  // nothing pushed) when absent; throws when the field is not a table. The
  // table stays on the stack for the reader's lifetime: restore the stack
  // top when done (the loader does so once, at the end).
  std::optional<LuaTableReader> table(const char* key) const;

  // Throws naming every key that is not in `allowed`, sorted so the message
  // does not depend on Lua's hash order; `allowed` is also listed.
  void rejectUnknownKeys(std::initializer_list<const char*> allowed) const;
  // Number of entries (any keys).
  int entryCount() const;

 private:
  std::optional<double> numberOnTop(const std::string& path) const;  // pops the value

  lua_State* L_;
  int index_;
  std::string source_;
  std::string path_;
};

// "number", "string", ... for messages; "inf", "nan" for non-finite numbers.
std::string describeLuaValue(lua_State* L, int index);

}  // namespace hemiroll::script
