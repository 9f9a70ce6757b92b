#pragma once
// Triangle order and simplified copies of a mesh for the GPU (meshoptimizer, Debian's
// libmeshoptimizer-dev). Pictures depend on the order only where two triangles tie in depth.
#include <cstddef>

#include "marble/mesh/mesh.h"

namespace marble {

// Reorders the triangles for the post-transform vertex cache (meshopt_optimizeVertexCache),
// then for overdraw (meshopt_optimizeOverdraw, at most 5 % worse for the cache), then the
// vertices in first-use order (meshopt_optimizeVertexFetchRemap; positions, normals and
// texture coordinates move together). The same triangles, the same vertices: only the order
// changes. Vertices no triangle uses are dropped.
void optimizeDrawOrder(Mesh& mesh);

struct SimplifiedMesh {
  Mesh mesh;                // compact: only the vertices its triangles use, in draw order
  float errorUnits = 0.0f;  // meshoptimizer's bound on how far the surface moved, scene units
};

// A copy with about `targetTriangles` triangles (meshopt_simplify: edge collapses under a
// quadric error), stopping earlier where a collapse would move the surface by more than
// `maxErrorUnits`. Vertices are welded by position first, so seams of normals or texture
// coordinates do not hold the simplifier back; the copy keeps each surviving vertex's normal.
// Slivers the collapses turn inside out are wound back (orientSlivers, closed_surface.h).
SimplifiedMesh simplifiedMesh(const Mesh& mesh, size_t targetTriangles, float maxErrorUnits);

}  // namespace marble
