#pragma once
// Reading a Lua file as the stand-alone interpreter would: a UTF-8
// byte-order mark skipped, a first line starting with '#' (a shebang)
// blanked, line numbers kept. DataFileLoader reads every data file (levels,
// protocols, sweep specs, scenarios) through readScriptText; LuaSandbox's
// runFile (bots) through skipInterpreterPrefix.

#include <cstdint>
#include <string>

#include "engine/files/FileKinds.h"

namespace hemiroll::script {

// The most any Lua file hemiroll reads may hold (levels, bots, protocols,
// sweep specs, scenarios are kilobytes): checked before a byte is read, so
// that a huge or endless file (/dev/zero, a 3 GB sparse file) costs nothing.
inline constexpr std::uintmax_t kMaxScriptFileBytes = files::kLuaSource.maxBytes;

// The file's text as above, read through the checked reader (engine/files).
// Throws ScriptError "path:1: ..." when it is missing, not a regular file
// (a FIFO, a device), larger than
// min(maxBytes, kMaxScriptFileBytes) or unreadable; `what` names the kind of
// file in those messages ("level file"), `limitName` the limit maxBytes is
// ("the memory limit").
std::string readScriptText(const std::string& path, const char* what, std::uintmax_t maxBytes = kMaxScriptFileBytes,
                           const char* limitName = "4 MiB limit of a Lua file");

// Skips the byte-order mark and blanks the '#' line of `text`, in place.
void skipInterpreterPrefix(std::string& text);

}  // namespace hemiroll::script
