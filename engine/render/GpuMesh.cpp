#include "engine/render/GpuMesh.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>
#include <utility>

namespace hemiroll::render {

GpuMesh GpuMesh::makeStatic(const MeshData& data) {
  GpuMesh m;
  m.create(data.primitive, data.vertices.data(), data.vertices.size(), data.vertices.size(), false);
  return m;
}

GpuMesh GpuMesh::makeDynamic(Primitive primitive, std::size_t capacity) {
  GpuMesh m;
  m.create(primitive, nullptr, 0, capacity, true);
  return m;
}

void GpuMesh::create(Primitive primitive, const Vertex* vertices, std::size_t count, std::size_t capacity,
                     bool dynamic) {
  mode_ = primitive == Primitive::Lines ? GL_LINES : GL_TRIANGLES;
  count_ = count;
  capacity_ = capacity;
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(capacity * sizeof(Vertex)), vertices,
               dynamic ? GL_DYNAMIC_DRAW : GL_STATIC_DRAW);
  // Attribute locations are fixed in the shaders (layout(location = N)).
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, color)));
  glBindVertexArray(0);
}

void GpuMesh::update(const Vertex* vertices, std::size_t count) {
  count_ = std::min(count, capacity_);
  if (count_ == 0) return;
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(count_ * sizeof(Vertex)), vertices);
}

void GpuMesh::draw() const {
  if (count_ == 0) return;
  glBindVertexArray(vao_);
  glDrawArrays(mode_, 0, GLsizei(count_));
}

void GpuMesh::drawRange(std::size_t first, std::size_t count) const {
  if (first >= count_) return;
  count = std::min(count, count_ - first);
  if (count == 0) return;
  glBindVertexArray(vao_);
  glDrawArrays(mode_, GLint(first), GLsizei(count));
}

void GpuMesh::release() {
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  vao_ = vbo_ = 0;
}

GpuMesh::~GpuMesh() { release(); }

GpuMesh::GpuMesh(GpuMesh&& o) noexcept
    : vao_(std::exchange(o.vao_, 0)), vbo_(std::exchange(o.vbo_, 0)), mode_(o.mode_), count_(o.count_),
      capacity_(o.capacity_) {}

GpuMesh& GpuMesh::operator=(GpuMesh&& o) noexcept {
  if (this != &o) {
    release();
    vao_ = std::exchange(o.vao_, 0);
    vbo_ = std::exchange(o.vbo_, 0);
    mode_ = o.mode_;
    count_ = o.count_;
    capacity_ = o.capacity_;
  }
  return *this;
}

}  // namespace hemiroll::render
