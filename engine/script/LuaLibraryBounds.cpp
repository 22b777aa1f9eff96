#include "engine/script/LuaLibraryBounds.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <lua.hpp>

#include "engine/script/LuaPatternBound.h"
#include "engine/script/LuaSandbox.h"

namespace hemiroll::script {

namespace {

// What one call may cost, worked out from its arguments before it runs.
// Estimators only look at the stack (and read a length once where a
// function would): they must not raise for arguments the function itself
// refuses, so that its own message ("bad argument #2 to 'rep'") stands.
struct Estimate {
  double worst = 1.0;    // steps at most
  double charge = 1.0;   // steps certainly taken (charged to the quota)
  char detail[200] = "";  // what makes it large, for a refusal
  const char* hint = "";  // what to do instead, for a refusal
};

using Estimator = void (*)(lua_State* L, Estimate& e);

struct Bounded {
  const char* name;  // "string.rep", for messages
  Estimator estimate;
};

// ---- argument readers that never raise and never convert in place

double lengthOf(lua_State* L, int i) {
  if (lua_type(L, i) == LUA_TSTRING) return static_cast<double>(lua_rawlen(L, i));
  if (lua_type(L, i) == LUA_TNUMBER) return 64.0;  // a number's text, converted by the function
  return 0.0;
}

// An integer argument, or `fallback` when absent; nullopt-like `ok` false
// when present but not an integer (the function will refuse it).
lua_Integer integerOr(lua_State* L, int i, lua_Integer fallback, bool& ok) {
  if (lua_isnoneornil(L, i)) return fallback;
  int isInteger = 0;
  const lua_Integer v = lua_tointegerx(L, i, &isInteger);
  if (!isInteger) ok = false;
  return v;
}

// The number of positions from i to j (inclusive) of a sequence of
// `length` after Lua's rules for negative and out-of-range positions.
double spanOf(double length, lua_Integer i, lua_Integer j) {
  double from = static_cast<double>(i), to = static_cast<double>(j);
  if (from < 0) from = std::max(length + from + 1.0, 1.0);
  if (from == 0) from = 1;
  if (to < 0) to = std::max(length + to + 1.0, 0.0);
  to = std::min(to, length);
  return to >= from ? to - from + 1.0 : 0.0;
}

// The sum of the lengths of arguments from `first` on.
double lengthsFrom(lua_State* L, int first) {
  double total = 0.0;
  for (int i = first; i <= lua_gettop(L); ++i) total += lengthOf(L, i);
  return total;
}

// ---- estimators

// Work linear in the strings given (upper, lower, reverse, len-like scans).
void linearInArguments(lua_State* L, Estimate& e) {
  e.worst = e.charge = 1.0 + lengthsFrom(L, 1) + lua_gettop(L);
}

void stringRep(lua_State* L, Estimate& e) {
  bool ok = true;
  const lua_Integer count = integerOr(L, 2, 0, ok);
  if (!ok || count <= 0) return;
  const double each = lengthOf(L, 1) + lengthOf(L, 3);
  // The loop runs `count` times even when nothing is copied.
  e.worst = e.charge = static_cast<double>(count) * (1.0 + each);
  std::snprintf(e.detail, sizeof e.detail, "%lld repetitions of %.0f bytes", static_cast<long long>(count), each);
}

void stringSub(lua_State* L, Estimate& e) {
  bool ok = true;
  const double length = lengthOf(L, 1);
  const lua_Integer i = integerOr(L, 2, 1, ok), j = integerOr(L, 3, -1, ok);
  e.worst = e.charge = 1.0 + (ok ? spanOf(length, i, j) : length);
}

// string.byte(s, i, j) and utf8.codepoint(s, i, j): one step per byte of
// the span i..j (j defaults to i).
void byteSpan(lua_State* L, Estimate& e) {
  bool ok = true;
  const double length = lengthOf(L, 1);
  const lua_Integer i = integerOr(L, 2, 1, ok);
  const lua_Integer j = integerOr(L, 3, i, ok);
  e.worst = e.charge = 1.0 + (ok ? spanOf(length, i, j) : length);
}

void stringFormat(lua_State* L, Estimate& e) {
  // %q may write a string out four times as long; each item at most a few
  // hundred bytes besides (Lua's own limits on widths and precisions).
  e.worst = e.charge = lengthOf(L, 1) + 4.0 * lengthsFrom(L, 2) + 512.0 * lua_gettop(L);
}

// string.pack: the format's options, each at most 16 bytes, plus the
// strings packed, plus any "cN" option's N (padding written byte by byte).
void stringPack(lua_State* L, Estimate& e) {
  std::size_t length = 0;
  const char* format = lua_type(L, 1) == LUA_TSTRING ? lua_tolstring(L, 1, &length) : "";
  double padding = 0.0;
  for (std::size_t k = 0; k < length; ++k) {
    if (format[k] != 'c') continue;
    double n = 0.0;
    while (k + 1 < length && format[k + 1] >= '0' && format[k + 1] <= '9') n = 10.0 * n + (format[++k] - '0');
    padding += n;
  }
  e.worst = e.charge = 16.0 * static_cast<double>(length) + lengthsFrom(L, 2) + padding;
}

void plainSearch(lua_State* L, Estimate& e, double subject, double needle) {
  // memchr for the first byte, then memcmp of the rest, from each start.
  e.worst = (subject + 1.0) * (needle + 1.0);
  e.charge = subject + needle;
  std::snprintf(e.detail, sizeof e.detail, "a plain search for %.0f bytes in %.0f", needle, subject);
  (void)L;
}

void patternSearch(lua_State* L, Estimate& e, PatternUse use) {
  std::size_t subjectLength = 0, patternLength = 0;
  if (lua_type(L, 1) != LUA_TSTRING || lua_type(L, 2) != LUA_TSTRING) {
    e.worst = e.charge = 1.0 + lengthsFrom(L, 1);
    return;
  }
  lua_tolstring(L, 1, &subjectLength);
  const char* pattern = lua_tolstring(L, 2, &patternLength);
  const double n = static_cast<double>(subjectLength), m = static_cast<double>(patternLength);
  const std::string_view p(pattern, patternLength);
  e.worst = patternStepBound(p, subjectLength, use);
  e.charge = n + m;
  std::snprintf(e.detail, sizeof e.detail, "the pattern (%d repeated items) on %zu characters", repeatedItems(p),
                subjectLength);
  e.hint = " (anchor it with '^', use fewer repeats or a shorter subject)";
}

bool hasSpecials(const char* p, std::size_t length) {
  for (std::size_t k = 0; k < length; ++k)
    if (std::strchr("^$*+?.([%-", p[k]) != nullptr) return true;
  return false;
}

void stringFind(lua_State* L, Estimate& e) {
  std::size_t patternLength = 0;
  const char* pattern = lua_type(L, 2) == LUA_TSTRING ? lua_tolstring(L, 2, &patternLength) : nullptr;
  if (pattern != nullptr && (lua_toboolean(L, 4) || !hasSpecials(pattern, patternLength)))
    plainSearch(L, e, lengthOf(L, 1), static_cast<double>(patternLength));
  else
    patternSearch(L, e, PatternUse::FindOrMatch);
}

void stringMatch(lua_State* L, Estimate& e) { patternSearch(L, e, PatternUse::FindOrMatch); }
void stringGmatch(lua_State* L, Estimate& e) { patternSearch(L, e, PatternUse::Gmatch); }

void stringGsub(lua_State* L, Estimate& e) {
  patternSearch(L, e, PatternUse::Gsub);
  // A replacement string is copied (its %0..%9 expanded) once per match;
  // an empty match adds nothing, so the output's size bounds nothing.
  if (lua_type(L, 3) == LUA_TSTRING) {
    bool ok = true;
    double matches = lengthOf(L, 1) + 1.0;
    const lua_Integer most = integerOr(L, 4, -1, ok);
    if (ok && most >= 0) matches = std::min(matches, static_cast<double>(most));
    e.worst += matches * lengthOf(L, 3);
    e.charge += lengthOf(L, 3);
  }
}

void argumentCount(lua_State* L, Estimate& e) { e.worst = e.charge = 1.0 + 4.0 * lua_gettop(L); }

// A table's length as the table functions will see it: the border of a
// plain table. False (and `e` says why) when it has a __len metamethod.
bool plainLength(lua_State* L, int t, double& length, Estimate& e, const char* name) {
  if (lua_type(L, t) != LUA_TTABLE) return false;  // the function refuses it itself
  if (luaL_getmetafield(L, t, "__len") != LUA_TNIL) {
    lua_pop(L, 1);
    e.worst = HUGE_VAL;
    std::snprintf(e.detail, sizeof e.detail,
                  "a table with a __len metamethod (%s takes a plain table's length: a __len could answer "
                  "differently when the function asks again)",
                  name);
    return false;
  }
  length = static_cast<double>(lua_rawlen(L, t));
  return true;
}

void tableInsert(lua_State* L, Estimate& e) {
  double n = 0.0;
  if (!plainLength(L, 1, n, e, "table.insert")) return;
  e.worst = n + 2.0;
  bool ok = true;
  const lua_Integer pos = lua_gettop(L) == 3 ? integerOr(L, 2, 1, ok) : static_cast<lua_Integer>(n) + 1;
  e.charge = ok ? std::max(1.0, n + 2.0 - static_cast<double>(pos)) : 1.0;
  std::snprintf(e.detail, sizeof e.detail, "moving %.0f elements", n);
}

void tableRemove(lua_State* L, Estimate& e) {
  double n = 0.0;
  if (!plainLength(L, 1, n, e, "table.remove")) return;
  e.worst = n + 2.0;
  bool ok = true;
  const lua_Integer pos = integerOr(L, 2, static_cast<lua_Integer>(n), ok);
  e.charge = ok ? std::max(1.0, n + 1.0 - static_cast<double>(pos)) : 1.0;
  std::snprintf(e.detail, sizeof e.detail, "moving %.0f elements", n);
}

void tableSort(lua_State* L, Estimate& e) {
  double n = 0.0;
  if (!plainLength(L, 1, n, e, "table.sort")) return;
  // Lua's quicksort picks its pivots at random once a partition is
  // unbalanced: n log n comparisons and moves, a few of each.
  e.worst = e.charge = 1.0 + 4.0 * n * (std::log2(n + 1.0) + 1.0);
  std::snprintf(e.detail, sizeof e.detail, "sorting %.0f elements", n);
}

void tableMove(lua_State* L, Estimate& e) {
  bool ok = true;
  const lua_Integer from = integerOr(L, 2, 0, ok), to = integerOr(L, 3, 0, ok);
  if (!ok || to < from) return;
  const double count = static_cast<double>(to) - static_cast<double>(from) + 1.0;
  e.worst = e.charge = count;
  std::snprintf(e.detail, sizeof e.detail, "moving %.0f elements", count);
}

// table.concat and table.unpack read #t when not given a last position:
// the length is read here, once (a __len runs once), and handed to the
// function as its explicit range, so it ranges over what was bounded.
double explicitRange(lua_State* L, int firstArg, Estimate& e) {
  if (lua_type(L, 1) != LUA_TTABLE) return 0.0;
  bool ok = true;
  const lua_Integer first = integerOr(L, firstArg, 1, ok);
  if (!ok) return 0.0;
  if (lua_isnoneornil(L, firstArg + 1)) {
    const lua_Integer length = luaL_len(L, 1);  // may run __len (Lua code, under the quota)
    if (lua_gettop(L) < firstArg) lua_settop(L, firstArg);
    lua_pushinteger(L, first);
    lua_replace(L, firstArg);
    lua_settop(L, firstArg);
    lua_pushinteger(L, length);
  }
  const lua_Integer last = integerOr(L, firstArg + 1, 0, ok);
  if (!ok || last < first) return 0.0;
  const double count = static_cast<double>(last) - static_cast<double>(first) + 1.0;
  std::snprintf(e.detail, sizeof e.detail, "%.0f elements", count);
  return count;
}

void tableConcat(lua_State* L, Estimate& e) {
  if (lua_type(L, 1) == LUA_TTABLE && lua_isnoneornil(L, 2)) {  // the default separator, made explicit
    if (lua_gettop(L) < 2) lua_settop(L, 2);
    lua_pushliteral(L, "");
    lua_replace(L, 2);
  }
  const double count = explicitRange(L, 3, e);
  e.worst = e.charge = 1.0 + count * (1.0 + lengthOf(L, 2));
}

void tableUnpack(lua_State* L, Estimate& e) { e.worst = e.charge = 1.0 + explicitRange(L, 2, e); }

// ---- the wrapper

// Upvalue 1: the library's own function; upvalue 2: its Bounded entry.
int boundedCall(lua_State* L) {
  const auto* bounded = static_cast<const Bounded*>(lua_touserdata(L, lua_upvalueindex(2)));
  Estimate e;
  bounded->estimate(L, e);
  LuaSandbox& sandbox = LuaSandbox::of(L);
  char why[512];
  switch (sandbox.admitLibraryCall(bounded->name, e.worst, e.charge, e.detail, why, sizeof why)) {
    case LuaSandbox::LibraryVerdict::Run: break;
    case LuaSandbox::LibraryVerdict::Refused: return luaL_error(L, "%s%s", why, e.hint);
    case LuaSandbox::LibraryVerdict::LimitReached: LuaSandbox::raiseLimit(L, why);
  }
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  // Called from C, the function cannot find the name it was called by:
  // its argument errors would say "bad argument #1 to '?'". They get the
  // name back (a memory error stays one: LuaSandbox recognises its text).
  if (lua_pcall(L, lua_gettop(L) - 1, LUA_MULTRET, 0) != LUA_OK) {
    if (lua_type(L, -1) == LUA_TSTRING && std::strstr(lua_tostring(L, -1), " to '?'") != nullptr) {
      char named[64];
      std::snprintf(named, sizeof named, " to '%s'", std::strchr(bounded->name, '.') != nullptr
                                                          ? std::strchr(bounded->name, '.') + 1
                                                          : bounded->name);
      luaL_gsub(L, lua_tostring(L, -1), " to '?'", named);
    }
    return lua_error(L);
  }
  if (!sandbox.libraryCallReturned(why, sizeof why)) LuaSandbox::raiseLimit(L, why);
  return lua_gettop(L);
}

void bound(lua_State* L, int lib, const char* field, const Bounded& entry) {
  lua_getfield(L, lib, field);
  if (!lua_iscfunction(L, -1)) {
    lua_pop(L, 1);
    return;
  }
  lua_pushlightuserdata(L, const_cast<Bounded*>(&entry));
  lua_pushcclosure(L, boundedCall, 2);
  lua_setfield(L, lib, field);
}

}  // namespace

void installLibraryBounds(lua_State* L, int stringLib, int tableLib, int utf8Lib, int baseLib) {
  static const Bounded kString[] = {
      {"string.byte", byteSpan},     {"string.char", argumentCount},   {"string.find", stringFind},
      {"string.format", stringFormat}, {"string.gmatch", stringGmatch},  {"string.gsub", stringGsub},
      {"string.lower", linearInArguments}, {"string.match", stringMatch}, {"string.rep", stringRep},
      {"string.reverse", linearInArguments}, {"string.sub", stringSub},   {"string.upper", linearInArguments},
      {"string.pack", stringPack},     {"string.packsize", linearInArguments}, {"string.unpack", linearInArguments},
  };
  static const Bounded kTable[] = {
      {"table.concat", tableConcat}, {"table.insert", tableInsert}, {"table.move", tableMove},
      {"table.pack", argumentCount}, {"table.remove", tableRemove}, {"table.sort", tableSort},
      {"table.unpack", tableUnpack},
  };
  static const Bounded kUtf8[] = {
      {"utf8.char", argumentCount}, {"utf8.codepoint", byteSpan}, {"utf8.len", linearInArguments},
      {"utf8.offset", linearInArguments},
  };
  static const Bounded kBase[] = {{"tonumber", linearInArguments}, {"select", argumentCount}};
  for (const Bounded& b : kString) bound(L, stringLib, std::strchr(b.name, '.') + 1, b);
  for (const Bounded& b : kTable) bound(L, tableLib, std::strchr(b.name, '.') + 1, b);
  for (const Bounded& b : kUtf8) bound(L, utf8Lib, std::strchr(b.name, '.') + 1, b);
  for (const Bounded& b : kBase) bound(L, baseLib, b.name, b);
}

}  // namespace hemiroll::script
