#pragma once
// Reading a Lua file as the stand-alone interpreter would: a UTF-8
// byte-order mark skipped, a first line starting with '#' (a shebang)
// blanked, line numbers kept. DataFileLoader reads every data file (levels,
// protocols, sweep specs, scenarios) through readScriptText; LuaSandbox's
// runFile (bots) through skipInterpreterPrefix.

#include <string>

namespace hemiroll::script {

// The file's text as above. Throws ScriptError "path:1: ..." when it is
// missing, not a regular file or unreadable; `what` names the kind of file
// in those messages ("level file").
std::string readScriptText(const std::string& path, const char* what);

// Skips the byte-order mark and blanks the '#' line of `text`, in place.
void skipInterpreterPrefix(std::string& text);

}  // namespace hemiroll::script
