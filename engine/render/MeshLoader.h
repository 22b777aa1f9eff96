#pragma once
// Meshes from files through assimp (glTF, GLB, OBJ and whatever else it
// reads): all meshes of the file, triangulated, with smooth normals where the
// file has none, centred on their bounding box and scaled to fit the unit
// sphere, so the renderer places any marker mesh like its procedural one.
// glTF/GLB files are y up as their specification says and are turned to the
// engine's z up; OBJ files are taken as they are (z up).
// A missing, unreadable or empty file is not an error here: the result says
// why and the caller draws its built-in fallback.

#include <optional>
#include <string>

#include "engine/render/MeshData.h"

namespace hemiroll::render {

struct LoadedMesh {
  std::optional<MeshData> mesh;  // empty on failure
  std::string error;             // "path: why" when empty
};

// `color` is used for vertices without colours in the file.
LoadedMesh loadMeshFile(const std::string& path, Rgba color = {1, 1, 1, 1});

}  // namespace hemiroll::render
