#pragma once
// Where the game's assets/ (shaders, meshes) are: $HEMIROLL_ASSETS if set,
// else assets/ beside the program or one level up (build/hemiroll in a
// checkout), else ./assets. Returns "" when none holds shaders/; the renderer
// then uses its built-in fallbacks and says so.

#include <string>

namespace hemiroll::game {

std::string findAssetsDirectory();

}  // namespace hemiroll::game
