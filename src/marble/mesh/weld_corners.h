#pragma once
// Welding a triangle soup's corners (STL stores every triangle's corners separately) into shared
// vertices, over threads.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace marble::mesh_detail {

struct WeldedCorners {
  std::vector<glm::vec3> positions;  // the distinct positions, in the order of their first corner
  std::vector<uint32_t> indices;     // indices[c]: the vertex of corner c
};

// Bit-identical positions (with -0 == +0; -0 is stored as +0) become one vertex; the i-th distinct
// position met in corner order becomes vertex i. That is exactly what inserting the corners one by
// one into a hash table gives (the ASCII STL scan's incremental welder, which
// tests/mesh_weld_test.cpp compares against), but computed in three passes: hashes over threads;
// each corner's first equal corner, the hash space split into one part per thread (every thread
// reads all hashes, keeps its own part's corners in its own table, so no locking and the same
// answer for any thread count); then one sequential pass numbering the first corners in order.
// `threads` = 0: one per core (parallel_for.h). Positions must be finite (NaN != NaN).
WeldedCorners weldCorners(std::vector<glm::vec3> corners, unsigned threads = 0);

}  // namespace marble::mesh_detail
