#pragma once
// The one error type of engine/render: a sentence naming the file (and line,
// for shaders) or the GL call that failed.

#include <stdexcept>
#include <string>

namespace hemiroll::render {

class RenderError : public std::runtime_error {
 public:
  explicit RenderError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace hemiroll::render
