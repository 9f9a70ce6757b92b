#pragma once
// Welding a triangle soup's corners (STL stores every triangle's corners separately) into shared
// vertices.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace marble::mesh_detail {

// Bit-identical positions (with -0 == +0; -0 is stored as +0) become one vertex, numbered in the
// order they are first met: an open-addressing table of vertex numbers (linear probing, load
// factor <= 1/2, doubled as needed), compared against the positions found so far.
// (add is inline: called once per corner, a call cost 15-20 % of the loop.)
class Welder {
public:
  // Room for `expectedVertices` before the first doubling.
  explicit Welder(size_t expectedVertices);

  // The vertex of `p`, appended to `positions` when new.
  uint32_t add(glm::vec3 p, std::vector<glm::vec3>& positions) {
    p = withoutMinusZero(p);
    const uint32_t bx = std::bit_cast<uint32_t>(p.x), by = std::bit_cast<uint32_t>(p.y), bz = std::bit_cast<uint32_t>(p.z);
    for (size_t slot = hashOf(p) & mask_;; slot = (slot + 1) & mask_) {
      const uint32_t v = slots_[slot];
      if (v == kEmpty) {
        const auto index = static_cast<uint32_t>(positions.size());
        positions.push_back(p);
        if (positions.size() * 2 > slots_.size()) grow(positions);  // places the new one too
        else slots_[slot] = index;
        return index;
      }
      const glm::vec3& q = positions[v];
      if (std::bit_cast<uint32_t>(q.x) == bx && std::bit_cast<uint32_t>(q.y) == by && std::bit_cast<uint32_t>(q.z) == bz)
        return v;
    }
  }

private:
  static constexpr uint32_t kEmpty = 0xFFFFFFFFu;

  static size_t hashOf(const glm::vec3& p) {
    const uint64_t bx = std::bit_cast<uint32_t>(p.x), by = std::bit_cast<uint32_t>(p.y), bz = std::bit_cast<uint32_t>(p.z);
    const uint64_t h = bx * 0x9E3779B97F4A7C15ull ^ by * 0xC2B2AE3D27D4EB4Full ^ bz * 0x165667B19E3779F9ull;
    return static_cast<size_t>(h ^ (h >> 31));
  }
  static glm::vec3 withoutMinusZero(glm::vec3 p) {
    if (p.x == 0.0f) p.x = 0.0f;
    if (p.y == 0.0f) p.y = 0.0f;
    if (p.z == 0.0f) p.z = 0.0f;
    return p;
  }
  size_t slotFor(const glm::vec3& p) const;
  void grow(const std::vector<glm::vec3>& positions);

  std::vector<uint32_t> slots_;
  size_t mask_ = 0;
};

struct WeldedCorners {
  std::vector<glm::vec3> positions;  // the distinct positions, in the order of their first corner
  std::vector<uint32_t> indices;     // indices[c]: the vertex of corner c
};

// The corners added to one Welder in order (the ASCII STL's chunks, joined). (Splitting the hash
// space over threads, each with its own table, was tried: the tables' cache misses cost 2.7x the
// CPU of this loop, and CPU time is what a shared machine's parse is short of.)
WeldedCorners weldCorners(const std::vector<glm::vec3>& corners);

}  // namespace marble::mesh_detail
