#include "engine/script/ScriptSourceFile.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/script/LevelSourceMap.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::script {

namespace {

// "name:12:" at the start: the message already has its line.
bool startsWithLine(const std::string& message, const std::string& name) {
  if (message.compare(0, name.size(), name) != 0 || message.size() <= name.size() + 1 || message[name.size()] != ':')
    return false;
  std::size_t i = name.size() + 1;
  const std::size_t digits = i;
  while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i]))) ++i;
  return i > digits && i < message.size() && message[i] == ':';
}

}  // namespace

std::string withSourceLine(const std::string& message, const std::string& name, std::string_view source) {
  if (startsWithLine(message, name)) return message;
  const std::string prefix = name + ": ";
  if (message.compare(0, prefix.size(), prefix) != 0) return name + ":1: " + message;
  const std::string rest = message.substr(prefix.size());
  const std::size_t colon = rest.find(": ");
  const std::string path = colon == std::string::npos ? "" : rest.substr(0, colon);
  const bool pathLike = !path.empty() && path.find(' ') == std::string::npos;
  const LevelSourceMap map(source);
  return name + ":" + std::to_string(map.lineOf(pathLike ? path : "")) + ": " + rest;
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
  // As the stand-alone interpreter: skip a UTF-8 byte-order mark, blank out a
  // first line starting with '#', keeping line numbers.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  if (!text.empty() && text.front() == '#') text.erase(0, std::min(text.find('\n'), text.size()));
  return text;
}

}  // namespace hemiroll::script
