#include "engine/script/LuaTableReader.h"

#include <algorithm>
#include <cmath>
#include <lua.hpp>
#include <vector>

#include "engine/script/ScriptError.h"

namespace hemiroll::script {

namespace {

// Builds "<open><inner><close>" by appending: GCC 12 warns (-Wrestrict, a
// false positive) on the equivalent chain of operator+ with a literal first.
std::string enclose(const char* open, const std::string& inner, const char* close) {
  std::string out(open);
  out.append(inner).append(close);
  return out;
}

}  // namespace

std::string describeLuaValue(lua_State* L, int index) {
  const int type = lua_type(L, index);
  if (type == LUA_TNUMBER) {
    const double v = lua_tonumber(L, index);
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  }
  return lua_typename(L, type);
}

LuaTableReader::LuaTableReader(lua_State* L, int index, std::string source, std::string path)
    : L_(L), index_(lua_absindex(L, index)), source_(std::move(source)), path_(std::move(path)) {}

std::string LuaTableReader::fieldPath(std::string_view key) const {
  if (key.empty()) return path_;
  if (path_.empty()) return std::string(key);
  if (key.front() == '[') return path_ + std::string(key);
  return path_ + "." + std::string(key);
}

void LuaTableReader::fail(std::string_view key, const std::string& message) const {
  throw FieldFailure(source_, {fieldPath(key), message});
}

void LuaTableReader::pushField(const char* key) const {
  lua_checkstack(L_, 2);
  lua_pushstring(L_, key);
  lua_rawget(L_, index_);
}

int LuaTableReader::typeOf(const char* key) const {
  pushField(key);
  const int type = lua_type(L_, -1);
  lua_pop(L_, 1);
  return type;
}

int LuaTableReader::typeAt(long long position) const {
  lua_checkstack(L_, 1);
  const int type = lua_rawgeti(L_, index_, static_cast<lua_Integer>(position));
  lua_pop(L_, 1);
  return type;
}

std::optional<double> LuaTableReader::numberOnTop(const std::string& path) const {
  const int type = lua_type(L_, -1);
  if (type == LUA_TNIL) {
    lua_pop(L_, 1);
    return std::nullopt;
  }
  // Strings are NOT numbers here, though Lua would convert "0.5": a quoted
  // number in a scenario is almost always a mistake worth reporting.
  const std::string got = describeLuaValue(L_, -1);
  const double value = type == LUA_TNUMBER ? lua_tonumber(L_, -1) : 0.0;
  lua_pop(L_, 1);
  if (type != LUA_TNUMBER) throw FieldFailure(source_, {path, "expected a number, got " + got});
  if (!std::isfinite(value)) throw FieldFailure(source_, {path, "expected a finite number, got " + got});
  return value;
}

std::optional<double> LuaTableReader::number(const char* key) const {
  pushField(key);
  return numberOnTop(fieldPath(key));
}

std::optional<double> LuaTableReader::numberAt(long long position) const {
  lua_checkstack(L_, 1);
  lua_rawgeti(L_, index_, static_cast<lua_Integer>(position));
  return numberOnTop(fieldPath(enclose("[", std::to_string(position), "]")));
}

std::optional<std::string> LuaTableReader::string(const char* key) const {
  pushField(key);
  const int type = lua_type(L_, -1);
  if (type == LUA_TNIL) {
    lua_pop(L_, 1);
    return std::nullopt;
  }
  if (type != LUA_TSTRING) {
    const std::string got = describeLuaValue(L_, -1);
    lua_pop(L_, 1);
    fail(key, "expected a string, got " + got);
  }
  std::size_t length = 0;
  const char* text = lua_tolstring(L_, -1, &length);
  std::string value(text, length);
  lua_pop(L_, 1);
  return value;
}

std::optional<LuaTableReader> LuaTableReader::table(const char* key) const {
  pushField(key);
  const int type = lua_type(L_, -1);
  if (type == LUA_TNIL) {
    lua_pop(L_, 1);
    return std::nullopt;
  }
  if (type != LUA_TTABLE) {
    const std::string got = describeLuaValue(L_, -1);
    lua_pop(L_, 1);
    fail(key, "expected a table, got " + got);
  }
  return LuaTableReader(L_, -1, source_, fieldPath(key));
}

int LuaTableReader::entryCount() const {
  int count = 0;
  lua_checkstack(L_, 3);
  lua_pushnil(L_);
  while (lua_next(L_, index_) != 0) {
    ++count;
    lua_pop(L_, 1);
  }
  return count;
}

void LuaTableReader::rejectUnknownKeys(std::initializer_list<const char*> allowed) const {
  std::vector<std::string> unknown;
  lua_checkstack(L_, 3);
  lua_pushnil(L_);
  while (lua_next(L_, index_) != 0) {
    lua_pop(L_, 1);  // the value; the key stays for lua_next
    if (lua_type(L_, -1) == LUA_TSTRING) {
      // lua_tolstring on a string key does not convert it, so lua_next is safe.
      std::size_t length = 0;
      const char* key = lua_tolstring(L_, -1, &length);
      const std::string name(key, length);
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return name == a; }))
        unknown.push_back(enclose("'", name, "'"));
    } else if (lua_isinteger(L_, -1)) {
      unknown.push_back(enclose("[", std::to_string(lua_tointeger(L_, -1)), "]"));
    } else {
      unknown.push_back(enclose("[", describeLuaValue(L_, -1), " key]"));
    }
  }
  if (unknown.empty()) return;
  std::sort(unknown.begin(), unknown.end());
  std::string list, expected;
  for (const std::string& u : unknown) list += (list.empty() ? "" : ", ") + u;
  for (const char* a : allowed) expected += (expected.empty() ? "" : ", ") + std::string(a);
  fail("", std::string(unknown.size() == 1 ? "unknown field " : "unknown fields ") + list +
               " (expected " + (allowed.size() == 0 ? std::string("no fields") : "one of: " + expected) + ")");
}

}  // namespace hemiroll::script
