#pragma once
// Where the game's shipped folders are, wherever it was started from (issue
// 27: started from another folder, it found assets/ but not levels/):
//   assets/ (shaders, meshes): $HEMIROLL_ASSETS, else beside the program or
//           one level up (build/hemiroll in a checkout), else ./assets;
//           the first that holds shaders/;
//   levels/ (*.lua): $HEMIROLL_LEVELS, else ./levels (a player's own levels
//           in the folder they started from come first), else beside the
//           program or one level up; the first that holds a *.lua file.
// "" when none does: the renderer then uses its built-in shaders, and the
// level select says where it looked.

#include <filesystem>
#include <string>
#include <vector>

namespace hemiroll::game {

// The running program (/proc/self/exe); "" when it cannot be read.
std::filesystem::path programPath();

// The folders searched for levels/, in order, for a program at `program`.
std::vector<std::filesystem::path> levelsDirectoryCandidates(const std::filesystem::path& program = programPath());

std::string findAssetsDirectory();
std::string findLevelsDirectory(const std::filesystem::path& program = programPath());

// A level named on the command line: as given when that file exists, else
// the file of the same name in `levelsDir` when that exists (so that
// `hemiroll play levels/paper_reaching.lua` works from any folder), else as
// given (the loader then says it is missing).
std::string resolveLevelPath(const std::string& level, const std::string& levelsDir);

}  // namespace hemiroll::game
