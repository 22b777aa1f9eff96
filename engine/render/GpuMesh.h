#pragma once
// A mesh on the GPU: one vertex array and one vertex buffer in the Vertex
// layout of MeshData.h. Static meshes are uploaded once; dynamic ones (lines
// that change every frame: the trace, the spring, the zones) get a fixed
// capacity at creation and are rewritten in place, so a frame allocates
// neither CPU nor GPU memory. Needs a current GL context; move-only.

#include <cstddef>

#include "engine/render/MeshData.h"

namespace hemiroll::render {

class GpuMesh {
 public:
  GpuMesh() = default;
  static GpuMesh makeStatic(const MeshData& data);
  static GpuMesh makeDynamic(Primitive primitive, std::size_t capacity);
  ~GpuMesh();
  GpuMesh(GpuMesh&& other) noexcept;
  GpuMesh& operator=(GpuMesh&& other) noexcept;
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  // Dynamic meshes: replaces the contents; vertices beyond capacity are dropped.
  void update(const Vertex* vertices, std::size_t count);
  void draw() const;
  // Vertices [first, first + count) of the current contents (clipped to them).
  void drawRange(std::size_t first, std::size_t count) const;
  std::size_t count() const { return count_; }
  std::size_t capacity() const { return capacity_; }
  bool valid() const { return vao_ != 0; }

 private:
  void create(Primitive primitive, const Vertex* vertices, std::size_t count, std::size_t capacity, bool dynamic);
  void release();
  unsigned vao_ = 0, vbo_ = 0;
  unsigned mode_ = 0;  // GL_TRIANGLES or GL_LINES
  std::size_t count_ = 0, capacity_ = 0;
};

}  // namespace hemiroll::render
