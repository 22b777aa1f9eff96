#pragma once
// The one error type of engine/platform: a sentence a player can act on
// ("no display: ..."), never an SDL error code alone.

#include <stdexcept>
#include <string>

namespace hemiroll::platform {

class PlatformError : public std::runtime_error {
 public:
  explicit PlatformError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace hemiroll::platform
