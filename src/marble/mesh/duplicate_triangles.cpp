#include "marble/mesh/duplicate_triangles.h"

#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

#include "marble/core/parallel_for.h"

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
  // Every triangle's hash first, over threads (reading three random positions is most of the
  // cost, and triangles are independent).
  std::vector<uint64_t> hashes(count);
  parallelFor(count, 100000, [&](size_t begin, size_t end) {
    for (size_t t = begin; t < end; ++t) hashes[t] = hashOf(canonical(mesh, t));
  });
  // Then in file order, open addressing over kept triangles, load factor <= 1/2. A slot holds a
  // kept triangle's position in the output (low 32 bits) and the high half of its hash, so that
  // a probe reads one word; a key is recomputed only when the whole hash matches (rare). The slot
  // of a triangle a few ahead is prefetched: the table is far larger than the caches.
  size_t capacity = 16;
  while (capacity < count * 2) capacity *= 2;
  const size_t mask = capacity - 1;
  constexpr uint64_t kEmpty = UINT64_MAX;  // no triangle's slot: output positions are < 2^32 - 1
  std::vector<uint64_t> slots(capacity, kEmpty);
  std::vector<uint32_t> keptHashLow;  // the low half of each kept triangle's hash
  keptHashLow.reserve(count);
  constexpr size_t kAhead = 8;
  size_t kept = 0;
  for (size_t t = 0; t < count; ++t) {
    if (t + kAhead < count) __builtin_prefetch(&slots[static_cast<size_t>(hashes[t + kAhead]) & mask]);
    const uint64_t h = hashes[t];
    const uint32_t high = static_cast<uint32_t>(h >> 32);
    size_t slot = static_cast<size_t>(h) & mask;
    bool duplicate = false;
    std::optional<std::array<Corner, 3>> key;  // triangle t's, made at the first full hash match
    for (; slots[slot] != kEmpty; slot = (slot + 1) & mask) {
      const uint64_t entry = slots[slot];
      const uint32_t k = static_cast<uint32_t>(entry);
      if (static_cast<uint32_t>(entry >> 32) != high || keptHashLow[k] != static_cast<uint32_t>(h)) continue;
      if (!key) key = canonical(mesh, t);
      if (canonical(mesh, k) == *key) {
        duplicate = true;
        break;
      }
    }
    if (duplicate) continue;
    slots[slot] = (static_cast<uint64_t>(high) << 32) | kept;
    keptHashLow.push_back(static_cast<uint32_t>(h));
    if (kept != t)
      for (int i = 0; i < 3; ++i) mesh.indices[3 * kept + i] = mesh.indices[3 * t + i];
    ++kept;
  }
  const size_t removed = count - kept;
  mesh.indices.resize(3 * kept);
  return removed;
}

}  // namespace marble
