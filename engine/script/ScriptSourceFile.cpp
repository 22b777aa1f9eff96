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

std::string readScriptText(const std::string& path, const char* what) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw ScriptError(path + ":1: " + (std::filesystem::exists(path, error) ? "not a regular file" : "no such file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScriptError(path + ":1: cannot open the " + what);
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) throw ScriptError(path + ":1: cannot read the " + what);
  std::string text = content.str();
  skipInterpreterPrefix(text);
  return text;
}

}  // namespace hemiroll::script
