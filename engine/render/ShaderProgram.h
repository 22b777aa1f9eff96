#pragma once
// A linked GLSL program. compile() throws RenderError with "file:line: ..."
// for the first error GLSL reports (Mesa writes "0:LINE(COL): error", other
// drivers "0(LINE) : error"; both are mapped to the named file).
// loadWithFallback() reads NAME.vert/NAME.frag from a directory and falls
// back to built-in sources when a file is missing or broken, saying which
// and why in `note`. Needs a current GL context; move-only.

#include <string>

namespace hemiroll::render {

struct ShaderSource {
  std::string text;
  std::string name;  // file path (or "built-in NAME") for messages
};

class ShaderProgram {
 public:
  ShaderProgram() = default;
  static ShaderProgram compile(const ShaderSource& vertex, const ShaderSource& fragment);
  static ShaderProgram loadWithFallback(const std::string& directory, const std::string& name,
                                        const ShaderSource& builtinVertex, const ShaderSource& builtinFragment,
                                        std::string& note);
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  int uniform(const char* name) const;  // -1 when the program has none of that name
  unsigned id() const { return program_; }

 private:
  unsigned program_ = 0;
};

// "0:12(5): error: x" with file "a.frag" -> "a.frag:12: error: x" (each line
// of a GLSL log). Lines without a recognisable location keep "a.frag: ".
std::string mapShaderLog(const std::string& log, const std::string& file);

}  // namespace hemiroll::render
