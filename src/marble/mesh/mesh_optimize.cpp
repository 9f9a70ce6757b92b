#include "marble/mesh/mesh_optimize.h"

#include <meshoptimizer.h>

#include <algorithm>

#include "marble/mesh/closed_surface.h"

namespace marble {

namespace {

template <typename T>
void remapStream(std::vector<T>& stream, const std::vector<unsigned int>& remap, size_t uniqueCount) {
  if (stream.empty()) return;
  std::vector<T> out(uniqueCount);
  meshopt_remapVertexBuffer(out.data(), stream.data(), stream.size(), sizeof(T), remap.data());
  stream = std::move(out);
}

// Vertices in the order the triangles first use them; unused ones dropped.
void compactVertices(Mesh& mesh) {
  std::vector<unsigned int> remap(mesh.positions.size());
  const size_t unique =
      meshopt_optimizeVertexFetchRemap(remap.data(), mesh.indices.data(), mesh.indices.size(), mesh.positions.size());
  meshopt_remapIndexBuffer(mesh.indices.data(), mesh.indices.data(), mesh.indices.size(), remap.data());
  remapStream(mesh.positions, remap, unique);
  remapStream(mesh.normals, remap, unique);
  remapStream(mesh.texcoords, remap, unique);
}

}  // namespace

void optimizeDrawOrder(Mesh& mesh) {
  if (mesh.indices.empty() || mesh.positions.empty()) return;
  const size_t n = mesh.indices.size();
  std::vector<unsigned int> cached(n);
  meshopt_optimizeVertexCache(cached.data(), mesh.indices.data(), n, mesh.positions.size());
  // 1.05: meshoptimizer's recommended trade (overdraw saved for at most 5 % more vertex work).
  meshopt_optimizeOverdraw(mesh.indices.data(), cached.data(), n, &mesh.positions[0].x, mesh.positions.size(),
                           sizeof(glm::vec3), 1.05f);
  compactVertices(mesh);
}

SimplifiedMesh simplifiedMesh(const Mesh& mesh, size_t targetTriangles, float maxErrorUnits) {
  SimplifiedMesh result;
  if (mesh.indices.empty() || mesh.positions.empty()) return result;
  const size_t n = mesh.indices.size();
  const size_t vertices = mesh.positions.size();
  const float* positions = &mesh.positions[0].x;
  // Welded by position: a vertex split for its normal or texture coordinate is one vertex to
  // the simplifier (otherwise every seam is a border it must keep).
  std::vector<unsigned int> welded(n);
  meshopt_generateShadowIndexBuffer(welded.data(), mesh.indices.data(), n, positions, vertices, sizeof(glm::vec3),
                                    sizeof(glm::vec3));
  // meshopt_simplify takes the error relative to the mesh's extent.
  const float scale = meshopt_simplifyScale(positions, vertices, sizeof(glm::vec3));
  const float relativeError = scale > 0.0f ? maxErrorUnits / scale : 0.0f;
  std::vector<unsigned int> simplified(n);
  float resultRelative = 0.0f;
  const size_t count = meshopt_simplify(simplified.data(), welded.data(), n, positions, vertices, sizeof(glm::vec3),
                                        std::min(n, targetTriangles * 3), relativeError, 0, &resultRelative);
  simplified.resize(count);
  result.errorUnits = resultRelative * scale;
  result.mesh.positions = mesh.positions;
  result.mesh.normals = mesh.normals;
  result.mesh.texcoords = mesh.texcoords;
  result.mesh.indices = std::move(simplified);
  orientSlivers(result.mesh);  // so that a closed copy stays closed one way round (closed_surface.h)
  optimizeDrawOrder(result.mesh);  // also drops the vertices no triangle uses any more
  return result;
}

}  // namespace marble
