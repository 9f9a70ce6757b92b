#include "marble/mesh/duplicate_triangles.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "marble/core/parallel_for.h"
#include "marble/mesh/point_ids.h"

namespace marble {
namespace {

using Key = std::array<uint32_t, 3>;

// The triangle's smallest rotation (as a sequence of points): one key for all three rotations, a
// different one for the reversed winding. (With three distinct points it starts at the lowest;
// a triangle with a repeated point needs the full comparison: "lowest first" would give (a, b, a)
// and its rotation (a, a, b) two keys.) (Points are positions compared bit for bit with
// -0 == +0, point_ids.h: equal keys are exactly equal corner positions in the same cyclic order.)
// An index out of range (only possible through the API: loadMesh checks them first) is its own
// point, above every real one.
Key canonical(const Mesh& mesh, const std::vector<uint32_t>& point, size_t t) {
  const uint32_t n = static_cast<uint32_t>(point.size());
  auto of = [&](uint32_t v) { return v < n ? point[v] : v; };
  const Key c = {of(mesh.indices[3 * t]), of(mesh.indices[3 * t + 1]), of(mesh.indices[3 * t + 2])};
  if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
    return std::min({c, Key{c[1], c[2], c[0]}, Key{c[2], c[0], c[1]}});
  size_t first = 0;
  if (c[1] < c[first]) first = 1;
  if (c[2] < c[first]) first = 2;
  return {c[first], c[(first + 1) % 3], c[(first + 2) % 3]};
}

// The three words folded in, then MurmurHash3's 64-bit finalizer, so that the low bits (the
// table index) depend on every bit of every point.
uint64_t hashOf(const Key& key) {
  uint64_t h = (static_cast<uint64_t>(key[0]) << 32 | key[1]) * 0x9FB21C651E98DF25ull;
  h = (h ^ (h >> 29) ^ key[2]) * 0xC2B2AE3D27D4EB4Full;
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 33;
  h *= 0xC4CEB9FE1A85EC53ull;
  h ^= h >> 33;
  return h;
}

}  // namespace

size_t removeDuplicateTriangles(Mesh& mesh) { return removeDuplicateTriangles(mesh, pointIds(mesh.positions)); }

size_t removeDuplicateTriangles(Mesh& mesh, const std::vector<uint32_t>& point) {
  const size_t count = mesh.indices.size() / 3;
  if (count < 2) return 0;
  // Every triangle's hash first, over threads (triangles are independent).
  std::vector<uint64_t> hashes(count);
  parallelFor(count, 100000, [&](size_t begin, size_t end) {
    for (size_t t = begin; t < end; ++t) hashes[t] = hashOf(canonical(mesh, point, t));
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
    std::optional<Key> key;  // triangle t's, made at the first full hash match
    for (; slots[slot] != kEmpty; slot = (slot + 1) & mask) {
      const uint64_t entry = slots[slot];
      const uint32_t k = static_cast<uint32_t>(entry);
      if (static_cast<uint32_t>(entry >> 32) != high || keptHashLow[k] != static_cast<uint32_t>(h)) continue;
      if (!key) key = canonical(mesh, point, t);
      if (canonical(mesh, point, k) == *key) {
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
