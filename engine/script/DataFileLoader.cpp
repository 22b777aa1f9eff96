#include "engine/script/DataFileLoader.h"

#include <lua.hpp>

#include <cctype>

#include "engine/script/LevelSourceMap.h"
#include "engine/script/ScriptError.h"
#include "engine/script/ScriptSourceFile.h"

namespace hemiroll::script {

namespace {

// Restores the Lua stack on every exit, exceptions included: readers leave
// the tables they open on it.
class StackTop {
 public:
  explicit StackTop(lua_State* L) : L_(L), top_(lua_gettop(L)) {}
  ~StackTop() { lua_settop(L_, top_); }
  StackTop(const StackTop&) = delete;
  StackTop& operator=(const StackTop&) = delete;

 private:
  lua_State* L_;
  int top_;
};

// "name:12:" at the start: Lua has placed the message already.
bool startsWithLine(const std::string& message, const std::string& name) {
  if (message.compare(0, name.size(), name) != 0 || message.size() <= name.size() + 1 || message[name.size()] != ':')
    return false;
  std::size_t i = name.size() + 1;
  const std::size_t digits = i;
  while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i]))) ++i;
  return i > digits && i < message.size() && message[i] == ':';
}

// A failure that names no field. Lua's own messages ("name:3: ...") are kept;
// the sandbox's "name: memory limit ..." has no place of its own and gets the
// line of the returned table (where the data is); anything else, such as a
// required module's "lib/vec.lua:4: ...", goes behind "name:1: " so that
// every message starts with the file it was loading.
std::string placed(const std::string& message, const std::string& name, std::string_view source) {
  if (startsWithLine(message, name)) return message;
  const std::string prefix = name + ": ";
  if (message.compare(0, prefix.size(), prefix) != 0) return name + ":1: " + message;
  return name + ":" + std::to_string(LevelSourceMap(source).lineOf("")) + ": " + message.substr(prefix.size());
}

// A reader's failure at the line its field is written on (the line of the
// nearest written parent, or of the returned table, when it is computed).
std::string placed(const FieldError& error, const std::string& name, std::string_view source) {
  const int line = LevelSourceMap(source).lineOf(error.field);
  return name + ":" + std::to_string(line) + ": " + (error.field.empty() ? "" : error.field + ": ") + error.message;
}

}  // namespace

std::string DataFileLoader::readFile(const std::string& path) const {
  // The text must fit the Lua state's memory to be compiled at all.
  return readScriptText(path, kind_.file, limits_.memoryLimitBytes, "memory limit");
}

void DataFileLoader::run(std::string_view source, const std::string& name,
                         const std::function<void(const DataTable&)>& read) const {
  auto sandbox = std::make_shared<LuaSandbox>(limits_);
  if (prepare_) prepare_(*sandbox);
  lua_State* L = sandbox->state();
  const StackTop restore(L);
  try {
    sandbox->runChunk(source, name, 1);
    if (lua_type(L, -1) != LUA_TTABLE) {
      const std::string got = describeLuaValue(L, -1);
      throw FieldFailure(name, {"", std::string("the ") + kind_.table + " must return a table, got " + got});
    }
    const LuaTableReader top(L, -1, name, "");
    read(DataTable{top, sandbox});
  } catch (const FieldFailure& e) {
    // A reader of another file's table (none today) has no line here.
    if (e.source() != name) throw ScriptError(placed(e.what(), name, source));
    throw ScriptError(placed(e.error(), name, source));
  } catch (const ScriptError& e) {
    throw ScriptError(placed(e.what(), name, source));
  }
}

}  // namespace hemiroll::script
