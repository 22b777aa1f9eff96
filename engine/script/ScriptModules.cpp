#include "engine/script/ScriptModules.h"

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <lua.hpp>
#include <new>
#include <type_traits>

#include "engine/files/CheckedFile.h"
#include "engine/task/EngineRandom.h"
#include "engine/script/TaskNames.h"

namespace hemiroll::script {

namespace {

// Registry key of the engine table, so that a script replacing its global
// `hemiroll` cannot hide the table from the engine.
constexpr const char* kEngineTableKey = "hemiroll.engine";
// Longest module name; anything longer is a mistake or an attack.
constexpr std::size_t kMaxModuleName = 200;
// Marks a module whose chunk is running, to catch circular requires.
char kLoadingSentinel;

// nullptr when `name` is dot-separated segments of [A-Za-z0-9_]; otherwise a
// static sentence. Plain C: called from inside Lua.
const char* moduleNameProblem(const char* name, std::size_t length) {
  if (length == 0) return "the name is empty";
  if (length > kMaxModuleName) return "the name is longer than 200 characters";
  bool segmentEmpty = true;
  for (std::size_t i = 0; i < length; ++i) {
    const char c = name[i];
    if (c == '.') {
      if (segmentEmpty) return "a name segment is empty (\"..\", or a leading or trailing '.')";
      segmentEmpty = true;
    } else if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_') {
      segmentEmpty = false;
    } else {
      return "only letters, digits, '_' and '.' between segments are allowed (no '/', no path)";
    }
  }
  if (segmentEmpty) return "a name segment is empty (\"..\", or a leading or trailing '.')";
  return nullptr;
}

// require(name). Upvalues: 1 scripts directory, 2 cache table, 3 environment.
// Holds no C++ objects: every Lua call here may raise.
int sandboxRequire(lua_State* L) {
  std::size_t length = 0;
  const char* name = luaL_checklstring(L, 1, &length);
  if (const char* problem = moduleNameProblem(name, length))
    return luaL_error(L, "require('%s'): bad module name: %s", name, problem);
  lua_settop(L, 1);
  const int cache = lua_upvalueindex(2);

  lua_pushvalue(L, 1);
  lua_rawget(L, cache);  // 2: cached value or nil
  if (lua_touserdata(L, 2) == &kLoadingSentinel) return luaL_error(L, "require('%s'): circular require", name);
  if (!lua_isnil(L, 2)) return 1;
  lua_pop(L, 1);

  const char* directory = lua_tostring(L, lua_upvalueindex(1));
  if (directory == nullptr || directory[0] == '\0')
    return luaL_error(L, "require('%s'): modules are not available here (no scripts directory)", name);
  const char* relative = luaL_gsub(L, name, ".", "/");                        // 2
  const char* path = lua_pushfstring(L, "%s/%s.lua", directory, relative);  // 3
  // Checked as every file read is (engine/files): a regular file (a FIFO
  // would hang the read) within the Lua file cap.
  const files::CheckedRead sized = files::checkedSize(path, files::kLuaSource);
  if (!sized.ok) {
    if (std::strstr(sized.error, ": no such file") != nullptr)
      return luaL_error(L, "require('%s'): no module file %s", name, path);
    return luaL_error(L, "require('%s'): %s", name, sized.error);
  }
  // The file must be inside the scripts folder once links are followed: a
  // link out of it (to /etc/shadow, say) would be read and its text shown in
  // the syntax error.
  char realFile[PATH_MAX], realDirectory[PATH_MAX];
  if (realpath(path, realFile) == nullptr || realpath(directory, realDirectory) == nullptr)
    return luaL_error(L, "require('%s'): cannot resolve %s", name, path);
  const std::size_t directoryLength = std::strlen(realDirectory);
  if (std::strncmp(realFile, realDirectory, directoryLength) != 0 || realFile[directoryLength] != '/')
    return luaL_error(L, "require('%s'): %s leads outside the scripts folder (a link?)", name, path);
  const std::size_t size = static_cast<std::size_t>(sized.size);
  char* buffer = static_cast<char*>(lua_newuserdatauv(L, size + 1, 0));  // 4 (may raise: nothing open yet)
  // Read from the resolved file: the same one the check above looked at.
  const files::CheckedRead read = files::readCheckedInto(realFile, files::kLuaSource, buffer, size);
  if (!read.ok) return luaL_error(L, "require('%s'): %s", name, read.error);
  if (read.size != size) return luaL_error(L, "require('%s'): %s changed while it was read", name, path);
  const char* text = buffer;
  std::size_t textSize = size;
  if (textSize >= 3 && static_cast<unsigned char>(text[0]) == 0xEF && static_cast<unsigned char>(text[1]) == 0xBB &&
      static_cast<unsigned char>(text[2]) == 0xBF) {
    text += 3;
    textSize -= 3;
  }
  if (textSize > 0 && text[0] == LUA_SIGNATURE[0])
    return luaL_error(L, "require('%s'): %s is precompiled (binary) Lua; give Lua source text", name, path);

  lua_pushfstring(L, "@%s", path);  // 5
  if (luaL_loadbufferx(L, text, textSize, lua_tostring(L, 5), "t") != LUA_OK) return lua_error(L);  // 6
  lua_pushvalue(L, lua_upvalueindex(3));
  if (lua_setupvalue(L, 6, 1) == nullptr) lua_pop(L, 1);

  lua_pushvalue(L, 1);
  lua_pushlightuserdata(L, &kLoadingSentinel);
  lua_rawset(L, cache);
  lua_pushvalue(L, 1);
  const int status = lua_pcall(L, 1, 1, 0);  // 6: result or message
  if (status != LUA_OK) {
    lua_pushvalue(L, 1);
    lua_pushnil(L);
    lua_rawset(L, cache);
    return lua_error(L);  // the module's own "file:line: message"
  }
  if (lua_isnil(L, 6)) {
    lua_pop(L, 1);
    lua_pushboolean(L, 1);
  }
  lua_pushvalue(L, 1);
  lua_pushvalue(L, 6);
  lua_rawset(L, cache);
  return 1;
}

struct RandomState {
  EngineRandom generator;
  std::uint64_t seed;
};

// hemiroll.random([m [, n]]). Upvalue 1: the RandomState userdata.
int sandboxRandom(lua_State* L) {
  auto* state = static_cast<RandomState*>(lua_touserdata(L, lua_upvalueindex(1)));
  lua_Integer lo = 1, hi = 0;
  switch (lua_gettop(L)) {
    case 0:
      lua_pushnumber(L, state->generator.uniform());
      return 1;
    case 1:
      hi = luaL_checkinteger(L, 1);
      break;
    case 2:
      lo = luaL_checkinteger(L, 1);
      hi = luaL_checkinteger(L, 2);
      break;
    default:
      return luaL_error(L, "hemiroll.random: expected 0, 1 or 2 integer arguments");
  }
  luaL_argcheck(L, lo <= hi, lua_gettop(L), "interval is empty");
  lua_pushinteger(L, static_cast<lua_Integer>(state->generator.integer(lo, hi)));
  return 1;
}

int sandboxSeed(lua_State* L) {
  auto* state = static_cast<RandomState*>(lua_touserdata(L, lua_upvalueindex(1)));
  lua_pushinteger(L, static_cast<lua_Integer>(state->seed));
  return 1;
}

}  // namespace

void pushEngineTable(LuaSandbox& sandbox) {
  lua_State* L = sandbox.state();
  lua_checkstack(L, 3);
  if (lua_getfield(L, LUA_REGISTRYINDEX, kEngineTableKey) == LUA_TTABLE) return;
  lua_pop(L, 1);
  lua_newtable(L);
  lua_pushvalue(L, -1);
  lua_setfield(L, LUA_REGISTRYINDEX, kEngineTableKey);
  sandbox.pushEnvironment();
  lua_pushvalue(L, -2);
  lua_setfield(L, -2, "hemiroll");
  lua_pop(L, 1);
}

void installRequire(LuaSandbox& sandbox, const std::string& scriptsDir) {
  lua_State* L = sandbox.state();
  lua_checkstack(L, 4);
  sandbox.pushEnvironment();
  lua_pushlstring(L, scriptsDir.data(), scriptsDir.size());
  lua_newtable(L);
  sandbox.pushEnvironment();
  lua_pushcclosure(L, sandboxRequire, 3);
  lua_setfield(L, -2, "require");
  lua_pop(L, 1);
}

void installRandom(LuaSandbox& sandbox, std::uint64_t seed) {
  lua_State* L = sandbox.state();
  lua_checkstack(L, 4);
  pushEngineTable(sandbox);
  auto* state = static_cast<RandomState*>(lua_newuserdatauv(L, sizeof(RandomState), 0));
  static_assert(std::is_trivially_destructible_v<RandomState>, "Lua frees the userdata without a destructor");
  new (state) RandomState{EngineRandom(seed), seed};
  lua_pushvalue(L, -1);
  lua_pushcclosure(L, sandboxRandom, 1);
  lua_setfield(L, -3, "random");
  lua_pushcclosure(L, sandboxSeed, 1);
  lua_setfield(L, -2, "seed");
  lua_pop(L, 1);
}

std::string defaultScriptsDir(const std::string& filePath) {
  std::string directory = std::filesystem::path(filePath).parent_path().string();
  if (directory.empty()) directory.assign(1, '.');
  return directory + "/../scripts";
}

bool validModuleName(const std::string& name, std::string& why) {
  const char* problem = moduleNameProblem(name.c_str(), name.size());
  why = problem != nullptr ? problem : "";
  return why.empty();
}

}  // namespace hemiroll::script
