#include "engine/render/MeshLoader.h"

#include "engine/files/CheckedFile.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <assimp/Importer.hpp>
#include <cmath>
#include <limits>

namespace hemiroll::render {

namespace {

void normalise(MeshData& m) {
  float lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = std::numeric_limits<float>::max(), hi[k] = -lo[k];
  for (const Vertex& v : m.vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v.position[k]), hi[k] = std::max(hi[k], v.position[k]);
  float centre[3], radius = 0.0f;
  for (int k = 0; k < 3; ++k) centre[k] = 0.5f * (lo[k] + hi[k]);
  for (const Vertex& v : m.vertices) {
    float d2 = 0.0f;
    for (int k = 0; k < 3; ++k) d2 += (v.position[k] - centre[k]) * (v.position[k] - centre[k]);
    radius = std::max(radius, std::sqrt(d2));
  }
  const float scale = radius > 0.0f ? 1.0f / radius : 1.0f;
  for (Vertex& v : m.vertices)
    for (int k = 0; k < 3; ++k) v.position[k] = (v.position[k] - centre[k]) * scale;
}

}  // namespace

LoadedMesh loadMeshFile(const std::string& path, Rgba color) {
  LoadedMesh out;
  // Checked as every file read is (engine/files) before assimp opens it: a
  // FIFO would hang its open, a device or a huge file its read.
  if (const files::CheckedRead check = files::checkedSize(path.c_str(), files::kAsset); !check.ok) {
    out.error = check.error;
    return out;
  }
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_PreTransformVertices |
                aiProcess_SortByPType | aiProcess_FindInvalidData);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
    out.error = path + ": " + (importer.GetErrorString()[0] ? importer.GetErrorString() : "cannot read it");
    return out;
  }
  // glTF is y up by its specification; the engine is z up (RENDERING.md).
  // OBJ has no convention: hemiroll's are written z up.
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  const bool yUp = ext == ".gltf" || ext == ".glb";
  MeshData m;
  m.primitive = Primitive::Triangles;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[i];
    if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (unsigned k = 0; k < 3; ++k) {
        const unsigned idx = face.mIndices[k];
        const aiVector3D& p = mesh->mVertices[idx];
        const aiVector3D n = mesh->HasNormals() ? mesh->mNormals[idx] : aiVector3D(0, 0, 1);
        Rgba c = color;
        if (mesh->HasVertexColors(0)) {
          const aiColor4D& vc = mesh->mColors[0][idx];
          c = {vc.r, vc.g, vc.b, vc.a};
        }
        // +90 degrees about x: (x, y, z) -> (x, -z, y) takes y up to z up.
        if (yUp) m.vertices.push_back(makeVertex(p.x, -p.z, p.y, n.x, -n.z, n.y, c));
        else m.vertices.push_back(makeVertex(p.x, p.y, p.z, n.x, n.y, n.z, c));
      }
    }
  }
  const bool finite = std::all_of(m.vertices.begin(), m.vertices.end(), [](const Vertex& v) {
    return std::isfinite(v.position[0]) && std::isfinite(v.position[1]) && std::isfinite(v.position[2]) &&
           std::isfinite(v.normal[0]) && std::isfinite(v.normal[1]) && std::isfinite(v.normal[2]);
  });
  if (m.vertices.empty()) {
    out.error = path + ": has no triangles";
    return out;
  }
  if (!finite) {
    out.error = path + ": has non-finite vertices";
    return out;
  }
  normalise(m);
  out.mesh = std::move(m);
  return out;
}

}  // namespace hemiroll::render
