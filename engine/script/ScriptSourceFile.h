#pragma once
// What the loaders of data files written in Lua (levels, research protocols)
// share besides the table readers: reading the file as the stand-alone
// interpreter would, and giving a data error the line of its field.

#include <string>
#include <string_view>

namespace hemiroll::script {

// The file's text: a UTF-8 byte-order mark skipped, a first line starting
// with '#' blanked (line numbers kept). Throws ScriptError "path:1: ..." when
// it is missing, not a regular file or unreadable; `what` names the kind of
// file in those messages ("level file").
std::string readScriptText(const std::string& path, const char* what);

// "name: path: message" (a LuaTableReader failure) -> "name:LINE: path:
// message", the line of that field in `source` (LevelSourceMap). A message
// that already starts with "name:LINE:" is kept; anything else gets line 1.
std::string withSourceLine(const std::string& message, const std::string& name, std::string_view source);

}  // namespace hemiroll::script
