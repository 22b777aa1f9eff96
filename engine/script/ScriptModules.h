#pragma once
// Engine services installed into a LuaSandbox, as a global table `hemiroll`
// plus a global `require`. Level scripts and bots both get them.
//
//   require(name)         loads scripts/<name with '.' as '/'>.lua, once per
//                         sandbox (later calls return the cached value). The
//                         name must be dot-separated segments of [A-Za-z0-9_]
//                         ("bots.rose", "lib.vec"): no '/', no "..", no
//                         absolute path can be written. The file is read as
//                         text (bytecode is refused), runs in the same sandbox
//                         environment under the current call's quota and the
//                         memory cap, and returns one value (nil -> true).
//                         A module that requires itself (directly or not)
//                         fails with "circular require".
//   hemiroll.random()     a float in [0, 1) from the sandbox's EngineRandom;
//   hemiroll.random(m)    an integer in [1, m];
//   hemiroll.random(m, n) an integer in [m, n]. Deterministic per seed.
//   hemiroll.seed()       the seed in use (an integer).
//
// Without installRequire, `require` stays absent; without a scripts
// directory it reports that modules are unavailable.

#include <cstdint>
#include <string>

#include "engine/script/LuaSandbox.h"

namespace hemiroll::script {

// Installs `require` for modules under `scriptsDir` (a directory path,
// relative or absolute; messages name files as scriptsDir + "/a/b.lua").
void installRequire(LuaSandbox& sandbox, const std::string& scriptsDir);

// Installs hemiroll.random and hemiroll.seed with a generator seeded by
// `seed`. Calling it again reseeds.
void installRandom(LuaSandbox& sandbox, std::uint64_t seed);

// Pushes the sandbox's `hemiroll` table (creating it when absent) onto the
// stack; other engine services (the level runtime) add functions to it.
void pushEngineTable(LuaSandbox& sandbox);

// The scripts/ directory that belongs to a level or bot file by the
// repository layout: "<dir>/../scripts" for "<dir>/file.lua" (levels/x.lua ->
// "levels/../scripts"; a bare "x.lua" -> "./../scripts").
std::string defaultScriptsDir(const std::string& filePath);

// True for a module name require accepts ("bots.rose"); otherwise false and
// `why` says what is wrong.
bool validModuleName(const std::string& name, std::string& why);

}  // namespace hemiroll::script
