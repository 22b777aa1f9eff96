#include "engine/render/ShaderProgram.h"

#include <epoxy/gl.h>

#include <cctype>
#include <sstream>
#include <utility>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/render/RenderError.h"

namespace hemiroll::render {

namespace {

// Parses a leading "0:12(5):" (Mesa) or "0(12) :" (NVIDIA and others); on
// success returns the line and the rest after the location.
bool parseLocation(const std::string& line, int& lineNumber, std::string& rest) {
  std::size_t i = 0;
  while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
  if (i == 0 || i >= line.size()) return false;
  const char sep = line[i];
  if (sep != ':' && sep != '(') return false;
  std::size_t j = i + 1, k = j;
  while (k < line.size() && std::isdigit(static_cast<unsigned char>(line[k]))) ++k;
  if (k == j) return false;
  lineNumber = std::stoi(line.substr(j, k - j));
  std::size_t colon = line.find(':', k);
  if (colon == std::string::npos) return false;
  rest = line.substr(colon + 1);
  while (!rest.empty() && rest.front() == ' ') rest.erase(rest.begin());
  return true;
}

unsigned compileStage(unsigned type, const ShaderSource& source) {
  const unsigned shader = glCreateShader(type);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  int ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    int length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw RenderError(mapShaderLog(log.c_str(), source.name));
  }
  return shader;
}

// Through the checked reader, as every file: a shader is an asset.
bool readFile(const std::string& path, std::string& text) {
  try {
    text = files::readCheckedFile(path, files::kAsset);
    return true;
  } catch (const files::FileReadError&) {
    return false;
  }
}

}  // namespace

std::string mapShaderLog(const std::string& log, const std::string& file) {
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    int lineNumber = 0;
    std::string rest;
    if (parseLocation(line, lineNumber, rest))
      out += file + ":" + std::to_string(lineNumber) + ": " + rest + "\n";
    else
      out += file + ": " + line + "\n";
  }
  if (!out.empty()) out.pop_back();
  return out.empty() ? file + ": does not compile (the driver gave no log)" : out;
}

ShaderProgram ShaderProgram::compile(const ShaderSource& vertex, const ShaderSource& fragment) {
  const unsigned vs = compileStage(GL_VERTEX_SHADER, vertex);
  unsigned fs = 0;
  try {
    fs = compileStage(GL_FRAGMENT_SHADER, fragment);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  ShaderProgram p;
  p.program_ = glCreateProgram();
  glAttachShader(p.program_, vs);
  glAttachShader(p.program_, fs);
  glLinkProgram(p.program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  int ok = 0;
  glGetProgramiv(p.program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetProgramInfoLog(p.program_, sizeof log, nullptr, log);
    throw RenderError(vertex.name + " + " + fragment.name + ": do not link: " + log);
  }
  return p;
}

ShaderProgram ShaderProgram::loadWithFallback(const std::string& directory, const std::string& name,
                                              const ShaderSource& builtinVertex,
                                              const ShaderSource& builtinFragment, std::string& note) {
  note.clear();
  ShaderSource vertex{"", directory + "/" + name + ".vert"};
  ShaderSource fragment{"", directory + "/" + name + ".frag"};
  const bool haveVertex = readFile(vertex.name, vertex.text);
  const bool haveFragment = readFile(fragment.name, fragment.text);
  if (haveVertex && haveFragment) {
    try {
      return compile(vertex, fragment);
    } catch (const RenderError& e) {
      note = std::string(e.what()) + " (using the built-in " + name + " shaders)";
    }
  } else {
    note = (haveVertex ? fragment.name : vertex.name) + ": cannot read it (using the built-in " + name + " shaders)";
  }
  return compile(builtinVertex, builtinFragment);
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& o) noexcept : program_(std::exchange(o.program_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& o) noexcept {
  if (this != &o) {
    if (program_) glDeleteProgram(program_);
    program_ = std::exchange(o.program_, 0);
  }
  return *this;
}

void ShaderProgram::use() const { glUseProgram(program_); }

int ShaderProgram::uniform(const char* name) const { return glGetUniformLocation(program_, name); }

}  // namespace hemiroll::render
