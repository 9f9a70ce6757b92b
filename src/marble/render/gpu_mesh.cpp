#include "marble/render/gpu_mesh.h"

#include <vector>

#include "marble/gl/checked_calls.h"
#include "marble/gl/software_rasterizer.h"

namespace marble {

GpuMesh::GpuMesh(const Mesh& mesh)
    : vertices_(gl::Buffer::create()),
      indices_(gl::Buffer::create()),
      subsetIndices_(gl::Buffer::create()),
      vao_(gl::VertexArray::create()) {
  std::vector<float> interleaved;
  interleaved.reserve(mesh.positions.size() * 6);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0);
    interleaved.insert(interleaved.end(), {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z, n.x, n.y, n.z});
  }
  const auto vbytes = static_cast<GLsizeiptr>(interleaved.size() * sizeof(float));
  const auto ibytes = static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t));
  glNamedBufferStorage(vertices_.id(), vbytes, interleaved.data(), 0);
  glNamedBufferStorage(indices_.id(), ibytes, mesh.indices.data(), 0);
  bytes_ = static_cast<size_t>(vbytes + ibytes);
  // The cull before GL, only where GL rasterizes on the CPU (gl/software_rasterizer.h): its copy of
  // the positions, indices and planes and the subset's index buffer are not made on a GPU.
  if (gl::rasterizesInSoftware() && !mesh.indices.empty()) {
    screenCull_ = ScreenCullMesh(mesh);
    glNamedBufferStorage(subsetIndices_.id(), ibytes, nullptr, GL_MAP_WRITE_BIT);
    bytes_ += static_cast<size_t>(ibytes);
  }
  glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, 6 * sizeof(float));
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  glEnableVertexArrayAttrib(vao_.id(), 0);
  glEnableVertexArrayAttrib(vao_.id(), 1);
  glVertexArrayAttribFormat(vao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribFormat(vao_.id(), 1, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
  glVertexArrayAttribBinding(vao_.id(), 0, 0);
  glVertexArrayAttribBinding(vao_.id(), 1, 0);
  indexCount_ = static_cast<GLsizei>(mesh.indices.size());
  winding_ = closedSurfaceWinding(mesh);
  if (!mesh.positions.empty()) {
    boundsMin_ = boundsMax_ = mesh.positions.front();
    for (const glm::vec3& p : mesh.positions) {
      boundsMin_ = glm::min(boundsMin_, p);
      boundsMax_ = glm::max(boundsMax_, p);
    }
  }
  woundInward_ = signedVolume(mesh) < 0.0;
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_.id());
  gl::drawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

uint32_t* GpuMesh::mapSubset() const {
  if (!cullsOnCpu()) return nullptr;
  // Written in place: no copy of the subset (a glBufferSubData of the dragon's 140,000 indices
  // was 0.66 M instructions of its camera frame).
  return static_cast<uint32_t*>(glMapNamedBufferRange(subsetIndices_.id(), 0,
                                                      static_cast<GLsizeiptr>(indexCount_) * sizeof(uint32_t),
                                                      GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
}

void GpuMesh::unmapSubset() const { glUnmapNamedBuffer(subsetIndices_.id()); }

void GpuMesh::drawSubset(size_t count) const {
  if (count == 0 || count > static_cast<size_t>(indexCount_)) return;
  glVertexArrayElementBuffer(vao_.id(), subsetIndices_.id());
  glBindVertexArray(vao_.id());
  gl::drawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT, nullptr);
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
}

}  // namespace marble
