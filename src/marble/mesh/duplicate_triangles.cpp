#include "marble/mesh/duplicate_triangles.h"

#include <array>
#include <bit>
#include <cstdint>
#include <vector>

namespace marble {
namespace {

using Corner = std::array<uint32_t, 3>;

Corner bits(glm::vec3 p) {
  if (p.x == 0.0f) p.x = 0.0f;  // -0 -> +0
  if (p.y == 0.0f) p.y = 0.0f;
  if (p.z == 0.0f) p.z = 0.0f;
  return {std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y), std::bit_cast<uint32_t>(p.z)};
}

// The triangle's corners rotated so that the smallest comes first: one key for all three
// rotations, a different one for the reversed winding.
std::array<Corner, 3> canonical(const Mesh& mesh, size_t t) {
  std::array<Corner, 3> c = {bits(mesh.positions[mesh.indices[3 * t]]), bits(mesh.positions[mesh.indices[3 * t + 1]]),
                             bits(mesh.positions[mesh.indices[3 * t + 2]])};
  size_t first = 0;
  if (c[1] < c[first]) first = 1;
  if (c[2] < c[first]) first = 2;
  return {c[first], c[(first + 1) % 3], c[(first + 2) % 3]};
}

// The nine words folded in pairs, then MurmurHash3's 64-bit finalizer, so that the low bits
// (the table index) depend on every bit of every coordinate.
uint64_t hashOf(const std::array<Corner, 3>& key) {
  uint64_t h = 0x9E3779B97F4A7C15ull;
  for (const Corner& c : key) {
    h = (h ^ ((static_cast<uint64_t>(c[0]) << 32) | c[1])) * 0x9FB21C651E98DF25ull;
    h = (h ^ c[2]) * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
  }
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 33;
  h *= 0xC4CEB9FE1A85EC53ull;
  h ^= h >> 33;
  return h;
}

}  // namespace

size_t removeDuplicateTriangles(Mesh& mesh) {
  const size_t count = mesh.indices.size() / 3;
  if (count < 2) return 0;
  // Open addressing over kept triangles, load factor <= 1/2; each slot holds a kept triangle's
  // position in the output (its key is recomputed on a hash match, which is rare).
  size_t capacity = 16;
  while (capacity < count * 2) capacity *= 2;
  constexpr uint32_t kEmpty = UINT32_MAX;
  std::vector<uint32_t> slots(capacity, kEmpty);
  std::vector<uint64_t> hashes;  // of each kept triangle
  hashes.reserve(count);
  size_t kept = 0;
  for (size_t t = 0; t < count; ++t) {
    const auto key = canonical(mesh, t);
    const uint64_t h = hashOf(key);
    size_t slot = static_cast<size_t>(h) & (capacity - 1);
    bool duplicate = false;
    for (; slots[slot] != kEmpty; slot = (slot + 1) & (capacity - 1)) {
      const uint32_t k = slots[slot];
      if (hashes[k] == h && canonical(mesh, k) == key) {
        duplicate = true;
        break;
      }
    }
    if (duplicate) continue;
    slots[slot] = static_cast<uint32_t>(kept);
    hashes.push_back(h);
    if (kept != t)
      for (int i = 0; i < 3; ++i) mesh.indices[3 * kept + i] = mesh.indices[3 * t + i];
    ++kept;
  }
  const size_t removed = count - kept;
  mesh.indices.resize(3 * kept);
  return removed;
}

}  // namespace marble
