#pragma once
// Exact duplicate triangles, dropped when a mesh is loaded. A file with 100,000 copies of one
// triangle (an exporter bug, or a hostile file) would make every geometry pass draw the same
// pixels 100,000 times: the light-depth pass took 8-32 s for it. A copy adds nothing to the
// picture (same surface, same depth, same normal), so loadMesh keeps the first and says how many
// it dropped.
//
// "The same triangle": the same three corner positions (bit-exact, -0 == +0) in the same cyclic
// order, whatever corner the file starts with: (a, b, c), (b, c, a) and (c, a, b) are one
// triangle. The reversed winding (a, c, b) faces the other way; it is kept (a two-sided sheet is
// made of such pairs). Corners are compared by position, not by index, since formats like STL
// and OBJ may repeat a position under several indices; normals and texture coordinates are not
// compared (a copy with other texture coordinates would still be drawn over itself).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "marble/mesh/mesh.h"

namespace marble {

// Removes every triangle that repeats an earlier one as defined above, keeping the order of the
// rest; returns how many were removed. Vertices are left as they are.
size_t removeDuplicateTriangles(Mesh& mesh);
// The same with the vertices' points (pointIds(mesh.positions), point_ids.h) already found.
size_t removeDuplicateTriangles(Mesh& mesh, const std::vector<uint32_t>& pointIds);
// The same with the number of hash tables (one thread each) set: 0 = automatic (one per 100,000
// triangles, up to the hardware threads and 4). The result does not depend on it (tests).
size_t removeDuplicateTriangles(Mesh& mesh, const std::vector<uint32_t>& pointIds, unsigned tables);
// The triangles removeDuplicateTriangles removes (their indices, ascending), the mesh untouched.
std::vector<uint32_t> duplicateTriangles(const Mesh& mesh, const std::vector<uint32_t>& pointIds, unsigned tables = 0);
// Removes the triangles listed (ascending, no repeats), keeping the order of the rest; returns
// how many were removed.
size_t removeTriangles(Mesh& mesh, const std::vector<uint32_t>& sortedTriangles);

}  // namespace marble
