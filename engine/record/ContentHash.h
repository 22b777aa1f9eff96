#pragma once
// The identity of a file's bytes, as replays, sweep manifests and session
// manifests write it ("fnv1a-" and 16 hex digits): a changed level or spec
// is told apart from the one a recording was made with.

#include <string>
#include <string_view>

namespace hemiroll::record {

std::string contentHash(std::string_view bytes);
// contentHash of a Lua file's bytes (levels, protocols: read as
// files::kLuaSource); "" when it cannot be read.
std::string fileContentHash(const std::string& path);

}  // namespace hemiroll::record
