#pragma once
// Vertex normals as Blender makes them for a mesh that has none: each face's normal weighted by
// the angle of its corner at the vertex (Thürmer & Wüthrich 1998; Blender's mesh_normals.cc), and
// hard edges split where the two faces' normals are more than a crease angle apart (Blender's
// "Auto Smooth" angle).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "marble/core/page_buffer.h"
#include "marble/mesh/mesh.h"

namespace marble {

// kDefaultCreaseAngleDeg and kNoCreaseDeg are in mesh.h (loadMesh's default).

// Replaces mesh.normals by angle-weighted normals with hard edges at `creaseAngleDeg`:
// - Vertices at exactly the same position are the same point (so seams of texture coordinates,
//   or formats that store every triangle's own corners, like STL, do not split normals).
// - An edge is smooth when exactly two triangles share it, they use it in opposite directions
//   (consistent winding) and their normals are at most creaseAngleDeg apart; otherwise it is hard,
//   as in Blender with Auto Smooth. The corners around a point that are connected through smooth
//   edges form one fan and share one normal: the sum of their faces' normals, each weighted by
//   its corner's angle. With creaseAngleDeg >= 180 every corner of a point is in one fan.
// - A render vertex whose corners fall into several fans is duplicated (position and texture
//   coordinate copied), one copy per fan; the indices are rewritten to match.
// - Degenerate (zero-area) triangles add nothing; a vertex with no usable neighbour gets +Y.
void computeVertexNormals(Mesh& mesh, float creaseAngleDeg);
// The same with the vertices' points (pointIds(mesh.positions), point_ids.h) already found.
void computeVertexNormals(Mesh& mesh, float creaseAngleDeg, const std::vector<uint32_t>& pointIds);
// removeDuplicateTriangles (duplicate_triangles.h) and then computeVertexNormals, in one: the same
// mesh bit for bit, and the count removeDuplicateTriangles returns. The normals' point pass meets
// each point's triangles anyway; there two triangles with three distinct points are the same
// exactly when they share the two neighbours of the point, so the separate check's hash table
// (and its second look at every corner's point) is spared. loadMesh's path when a file has no
// normals.
// `recycled` (optional): memory the pass may take for its per-triangle records (48 bytes a
// triangle), resized, its contents overwritten; loadMesh hands over the file's bytes, whose pages
// the read already faulted in. The result does not depend on it.
size_t removeDuplicatesAndComputeNormals(Mesh& mesh, float creaseAngleDeg, const std::vector<uint32_t>& pointIds,
                                         PageBuffer* recycled = nullptr);

// The capacity that leaves room for the copies of vertices the crease normals append (a few % of
// the vertices: 2.3 % on the 1.6 M-triangle scan at 60°): a loader that sizes a large mesh's
// positions reserves it, so that the copies do not move the array (10 MB at 800,000 vertices,
// ≈ 1.5 ms on one thread); more copies than this only cost that move.
inline size_t capacityForCreaseCopies(size_t vertices) { return vertices + vertices / 16; }

}  // namespace marble
