#include "engine/script/LevelFieldChecks.h"

#include <lua.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace hemiroll::script {

namespace {

// Levenshtein distance, capped: names are short.
int editDistance(std::string_view a, std::string_view b) {
  std::vector<int> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string listOf(std::span<const char* const> names) {
  std::string out;
  for (const char* n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

}  // namespace

std::string bracketed(const std::string& inner) {
  std::string out(1, '[');
  out.append(inner).push_back(']');
  return out;
}

std::string positionKey(long long position) { return bracketed(std::to_string(position)); }

const char* nearestName(std::string_view name, std::initializer_list<const char*> allowed) {
  return nearestName(name, std::span<const char* const>(allowed.begin(), allowed.size()));
}

const char* nearestName(std::string_view name, std::span<const char* const> allowed) {
  const char* best = nullptr;
  int bestDistance = 3;
  for (const char* candidate : allowed) {
    const int d = editDistance(name, candidate);
    if (d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best;
}

void rejectUnknownLevelKeys(const LuaTableReader& table, std::initializer_list<const char*> allowed) {
  rejectUnknownLevelKeys(table, std::span<const char* const>(allowed.begin(), allowed.size()));
}

void rejectUnknownLevelKeys(const LuaTableReader& table, std::span<const char* const> allowed) {
  lua_State* L = table.state();
  std::vector<std::string> unknownNames;
  std::vector<std::string> unknownOthers;
  lua_checkstack(L, 3);
  lua_pushnil(L);
  while (lua_next(L, table.index()) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) == LUA_TSTRING) {
      std::size_t length = 0;
      const char* key = lua_tolstring(L, -1, &length);
      const std::string name(key, length);
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return name == a; }))
        unknownNames.push_back(name);
    } else if (lua_isinteger(L, -1)) {
      unknownOthers.push_back(positionKey(lua_tointeger(L, -1)));
    } else {
      unknownOthers.push_back(bracketed(describeLuaValue(L, -1) + " key"));
    }
  }
  const std::string expected = " (expected " + (allowed.size() == 0 ? std::string("no keys") : "one of: " + listOf(allowed)) + ")";
  if (!unknownNames.empty()) {
    const std::string first = *std::min_element(unknownNames.begin(), unknownNames.end());
    const char* suggestion = nearestName(first, allowed);
    table.fail(first, "unknown key '" + first + "'" +
                          (suggestion != nullptr ? " (did you mean '" + std::string(suggestion) + "'?)" : expected));
  }
  if (!unknownOthers.empty()) {
    std::sort(unknownOthers.begin(), unknownOthers.end());
    table.fail(unknownOthers.front(), "unexpected entry " + unknownOthers.front() + expected);
  }
}

std::optional<bool> readBool(const LuaTableReader& table, const char* key) {
  table.pushField(key);
  lua_State* L = table.state();
  const int type = lua_type(L, -1);
  const bool value = lua_toboolean(L, -1) != 0;
  const std::string got = describeLuaValue(L, -1);
  lua_pop(L, 1);
  if (type == LUA_TNIL) return std::nullopt;
  if (type != LUA_TBOOLEAN) table.fail(key, "expected true or false, got " + got);
  return value;
}

std::optional<int> readInteger(const LuaTableReader& table, const char* key, int lo, int hi) {
  const auto value = table.number(key);
  if (!value) return std::nullopt;
  if (*value != std::floor(*value) || *value < lo || *value > hi)
    table.fail(key, "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return static_cast<int>(*value);
}

std::optional<double> readPositive(const LuaTableReader& table, const char* key, const char* unit) {
  const auto value = table.number(key);
  if (value && *value <= 0.0) table.fail(key, std::string("must be a positive number (") + unit + ")");
  return value;
}

template <int N>
std::optional<std::array<double, N>> readVector(const LuaTableReader& table, const char* key, const char* what) {
  const int type = table.typeOf(key);
  if (type == LUA_TNIL) return std::nullopt;
  const std::string expected = "expected " + std::string(what);
  if (type != LUA_TTABLE) {
    table.pushField(key);
    const std::string got = describeLuaValue(table.state(), -1);
    lua_pop(table.state(), 1);
    table.fail(key, expected + ", got " + got);
  }
  const auto list = table.table(key);
  if (list->entryCount() != N) list->fail("", expected + " (" + std::to_string(list->entryCount()) + " entries given)");
  std::array<double, N> out{};
  for (int i = 0; i < N; ++i) {
    const auto v = list->numberAt(i + 1);
    if (!v) list->fail("", expected);
    out[static_cast<std::size_t>(i)] = *v;
  }
  lua_pop(table.state(), 1);  // the list table.table() pushed
  return out;
}

template std::optional<std::array<double, 2>> readVector<2>(const LuaTableReader&, const char*, const char*);
template std::optional<std::array<double, 3>> readVector<3>(const LuaTableReader&, const char*, const char*);

}  // namespace hemiroll::script
