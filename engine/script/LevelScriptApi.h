#pragma once
// The C functions behind the level API in the engine table (hemiroll.message,
// set_target, clear_target, succeed, fail, stage; LevelScript.h documents
// them). A friend of LevelScript: they reach the running LevelScript through
// the Lua registry and raise "only inside a level callback" when no callback
// is running. Internal to engine/script.

namespace hemiroll::script {

struct LevelScriptApi {
  // Registry field holding the sandbox's LevelScript (light userdata).
  static constexpr const char* kRegistryKey = "hemiroll.level";
};

}  // namespace hemiroll::script
