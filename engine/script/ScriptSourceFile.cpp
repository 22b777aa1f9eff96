#include "engine/script/ScriptSourceFile.h"

#include <algorithm>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/files/PrintableName.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::script {

namespace {

// The checked reader's sentence without the path it starts with: script
// errors put "path:1: " in front themselves.
std::string shortReason(const std::string& message, const std::string& path) {
  const std::string prefix = files::printable(path) + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

}  // namespace

void skipInterpreterPrefix(std::string& text) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  // Up to the newline, which stays: the chunk's lines keep their numbers.
  if (!text.empty() && text.front() == '#') text.erase(0, std::min(text.find('\n'), text.size()));
}

std::string readScriptText(const std::string& path, const char* what, std::uintmax_t maxBytes,
                           const char* limitName) {
  const std::uintmax_t limit = std::min(maxBytes, kMaxScriptFileBytes);
  std::string text;
  try {
    files::CheckedFile file(path, {what, files::kLuaSource.maxBytes});
    if (file.size() > limit)
      throw ScriptError(files::printablePath(path) + ":1: file is larger than the " +
                        (limit < kMaxScriptFileBytes ? limitName : "4 MiB limit of a Lua file"));
    text = file.readAll();
  } catch (const files::FileReadError& e) {
    throw ScriptError(files::printable(path) + ":1: " + shortReason(e.what(), path));
  }
  if (text.size() > limit)
    throw ScriptError(files::printablePath(path) + ":1: file is larger than the " +
                      (limit < kMaxScriptFileBytes ? limitName : "4 MiB limit of a Lua file"));
  skipInterpreterPrefix(text);
  return text;
}

}  // namespace hemiroll::script
