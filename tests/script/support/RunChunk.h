#pragma once
// What the sandbox's tests compare: a chunk's single result as a string
// (tostring-like), or its error prefixed with "ERROR: ".

#include <lua.hpp>
#include <string>

#include "engine/script/LuaSandbox.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::script::test {

// Runs `source` as chunk "t.lua" in `sandbox`.
inline std::string run(LuaSandbox& sandbox, const std::string& source) {
  try {
    sandbox.runChunk(source, "t.lua", 1);
  } catch (const ScriptError& e) {
    return std::string("ERROR: ") + e.what();
  }
  lua_State* L = sandbox.state();
  std::string out = lua_type(L, -1) == LUA_TBOOLEAN ? (lua_toboolean(L, -1) ? "true" : "false")
                    : lua_isstring(L, -1)           ? lua_tostring(L, -1)
                                                    : lua_typename(L, lua_type(L, -1));
  lua_pop(L, 1);
  return out;
}

// The same in a fresh sandbox.
inline std::string runFresh(const std::string& source, const SandboxLimits& limits = {}) {
  LuaSandbox sandbox(limits);
  return run(sandbox, source);
}

}  // namespace hemiroll::script::test
