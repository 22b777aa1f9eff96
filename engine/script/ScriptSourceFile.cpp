#include "engine/script/ScriptSourceFile.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/script/ScriptError.h"

namespace hemiroll::script {

void skipInterpreterPrefix(std::string& text) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  // Up to the newline, which stays: the chunk's lines keep their numbers.
  if (!text.empty() && text.front() == '#') text.erase(0, std::min(text.find('\n'), text.size()));
}

std::string readScriptText(const std::string& path, const char* what, std::uintmax_t maxBytes,
                           const char* limitName) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw ScriptError(path + ":1: " + (std::filesystem::exists(path, error) ? "not a regular file" : "no such file"));
  const std::uintmax_t limit = std::min(maxBytes, kMaxScriptFileBytes);
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) throw ScriptError(path + ":1: cannot read the " + what);
  if (size > limit)
    throw ScriptError(path + ":1: file is larger than the " + (limit < kMaxScriptFileBytes ? limitName : "4 MiB limit of a Lua file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScriptError(path + ":1: cannot open the " + what);
  // At most one byte past the limit, whatever the file grew to since.
  std::string text(static_cast<std::size_t>(limit) + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw ScriptError(path + ":1: cannot read the " + what);
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > limit)
    throw ScriptError(path + ":1: file is larger than the " + (limit < kMaxScriptFileBytes ? limitName : "4 MiB limit of a Lua file"));
  skipInterpreterPrefix(text);
  return text;
}

}  // namespace hemiroll::script
