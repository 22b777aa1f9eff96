#pragma once
// Every library function of the sandbox that can loop or allocate inside C,
// where no instruction hook runs and no clock is read, is bounded before it
// starts. Lua counts VM instructions; one call of string.rep('',
// math.maxinteger), table.move({}, 1, 1e15, 1, {}) or a plain string.find
// of an 8 MB needle in a 16 MB subject is one instruction that runs for
// hours. So each such function is replaced, in the library the scripts see
// and in the string metatable's, by a wrapper that
//   1. works out from its arguments, before it runs, the most steps it can
//      take (repetitions, ranges, the product of lengths for a plain search,
//      LuaPatternBound for patterns, n log n for sort, the bytes it reads or
//      writes) and refuses the call when that is over what one library call
//      may take (LuaSandbox::admitLibraryCall: SandboxLimits::
//      libraryStepBound, or less where the call's time limit is short);
//   2. charges the call's certain part (the bytes it reads and writes, the
//      elements it moves) to the instruction quota, so a loop of large calls
//      meets the quota as a loop of instructions does;
//   3. checks the clock before and after, so the call's wall-clock, CPU
//      and run budgets hold at every library call, not only every thousand
//      instructions.
// Functions whose work is constant (math, type, rawequal...) are left as
// they are. table.insert, table.remove and table.sort on a table with a
// __len metamethod are refused (the bound must be the length the function
// will use, and a __len may answer differently the second time);
// table.concat and table.unpack are given the length, read once, as their
// explicit range.

struct lua_State;

namespace hemiroll::script {

// Replaces the bounded functions in the library tables at stack indices
// `stringLib`, `tableLib`, `utf8Lib` and the base functions in `env`, in
// place. Called once while the sandbox is built.
void installLibraryBounds(lua_State* L, int stringLib, int tableLib, int utf8Lib, int baseLib);

}  // namespace hemiroll::script
