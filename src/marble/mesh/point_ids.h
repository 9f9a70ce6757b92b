#pragma once
// Points: render vertices at exactly the same position (bit for bit, -0 == +0) are one point. The
// crease normals (vertex_normals.h) and the duplicate-triangle check (duplicate_triangles.h) both
// work on points, so loadMesh finds them once and hands them to both.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace marble {

// Per vertex, its point: the lowest index of a vertex at the same position. (Only the ids'
// equality matters to the users, so a hash table, one pass, serves.) `tables` (0: automatic, one
// per 100,000 vertices up to 4 and the cores; at most 255) splits the table by hash, one thread
// each: the same ids for any count (tested).
std::vector<uint32_t> pointIds(const std::vector<glm::vec3>& positions, unsigned tables = 0);

}  // namespace marble
