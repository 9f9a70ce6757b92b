#include "marble/mesh/duplicate_triangles.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
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
  return removeDuplicateTriangles(mesh, point, 0);
}

size_t removeDuplicateTriangles(Mesh& mesh, const std::vector<uint32_t>& point, unsigned tables) {
  return removeTriangles(mesh, duplicateTriangles(mesh, point, tables));
}

std::vector<uint32_t> duplicateTriangles(const Mesh& mesh, const std::vector<uint32_t>& point, unsigned tables) {
  const size_t count = mesh.indices.size() / 3;
  if (count < 2) return {};
  if (tables == 0) tables = workerThreadCount(count, 100000, 4);
  // A triangle's table: the hash's top bits (the slot within a table takes its low bits). All
  // triangles of one key meet in one table, and each table is filled in file order, so each key's
  // first triangle is kept whatever the number of tables: the tables are independent (one thread
  // each, no locks) and the result is the one-table result.
  auto tableOf = [tables](uint64_t h) { return static_cast<unsigned>(((h >> 32) * tables) >> 32); };
  // Every triangle's hash first, over threads (triangles are independent), and each range's
  // count per table (to size the tables). Every element is written, so the array is left unset
  // (zeroing 13 MB at 1.6 M triangles would fault its pages in on the calling thread).
  const std::unique_ptr<uint64_t[]> hashes = std::make_unique_for_overwrite<uint64_t[]>(count);
  const unsigned hashRanges = workerThreadCount(count, 100000);
  std::vector<std::vector<size_t>> perRange(hashRanges, std::vector<size_t>(tables, 0));
  parallelFor(hashRanges, 1, [&](size_t first, size_t last) {
    for (size_t r = first; r < last; ++r) {
      std::vector<size_t> n(tables, 0);  // counted here, not in perRange[r]: no shared cache line
      for (size_t t = count * r / hashRanges, end = count * (r + 1) / hashRanges; t < end; ++t) {
        // The points of a triangle a few ahead, prefetched (its vertices are scattered).
        if (t + 8 < end)
          for (size_t k = 0; k < 3; ++k)
            if (const uint32_t v = mesh.indices[3 * (t + 8) + k]; v < point.size()) __builtin_prefetch(&point[v]);
        hashes[t] = hashOf(canonical(mesh, point, t));
        ++n[tableOf(hashes[t])];
      }
      perRange[r] = std::move(n);
    }
  });
  // Then each table in file order, open addressing, load factor <= 1/2. A slot holds a kept
  // triangle's index (low 32 bits) and the high half of its hash, so that a probe reads one word;
  // a key is recomputed only when the whole hash matches (rare). The indices are moved only after
  // all tables are done, so a kept triangle's key is read from its own place. The slot of a
  // triangle a few ahead is prefetched when it is this table's: the tables are far larger than
  // the caches.
  std::vector<std::vector<uint32_t>> dropped(tables);  // per table, ascending
  parallelFor(tables, 1, [&](size_t first, size_t last) {
    for (size_t table = first; table < last; ++table) {
      size_t members = 0;
      for (const std::vector<size_t>& n : perRange) members += n[table];
      size_t capacity = 16;
      while (capacity < members * 2) capacity *= 2;
      const size_t mask = capacity - 1;
      constexpr uint64_t kEmpty = UINT64_MAX;  // no triangle's slot: indices are < 2^32 - 1
      std::vector<uint64_t> slots(capacity, kEmpty);
      constexpr size_t kAhead = 16;
      for (size_t t = 0; t < count; ++t) {
        if (t + kAhead < count && tableOf(hashes[t + kAhead]) == table)
          __builtin_prefetch(&slots[static_cast<size_t>(hashes[t + kAhead]) & mask]);
        const uint64_t h = hashes[t];
        if (tableOf(h) != table) continue;
        const uint32_t high = static_cast<uint32_t>(h >> 32);
        size_t slot = static_cast<size_t>(h) & mask;
        bool duplicate = false;
        std::optional<Key> key;  // triangle t's, made at the first full hash match
        for (; slots[slot] != kEmpty; slot = (slot + 1) & mask) {
          const uint64_t entry = slots[slot];
          // The slot's high half first: reading hashes[k] on every probe is a cache miss each.
          if (static_cast<uint32_t>(entry >> 32) != high) continue;
          const uint32_t k = static_cast<uint32_t>(entry);
          if (hashes[k] != h) continue;
          if (!key) key = canonical(mesh, point, t);
          if (canonical(mesh, point, k) == *key) {
            duplicate = true;
            break;
          }
        }
        if (duplicate) dropped[table].push_back(static_cast<uint32_t>(t));
        else slots[slot] = (static_cast<uint64_t>(high) << 32) | t;
      }
    }
  });
  // The dropped triangles of all tables in file order.
  std::vector<uint32_t> drop;
  for (const std::vector<uint32_t>& d : dropped) drop.insert(drop.end(), d.begin(), d.end());
  std::sort(drop.begin(), drop.end());
  return drop;
}

size_t removeTriangles(Mesh& mesh, const std::vector<uint32_t>& drop) {
  if (drop.empty()) return 0;
  const size_t count = mesh.indices.size() / 3;
  // The kept triangles between two dropped ones moved down over the dropped.
  size_t kept = drop[0];
  for (size_t d = 0; d < drop.size(); ++d) {
    const size_t next = d + 1 < drop.size() ? drop[d + 1] : count;
    for (size_t t = drop[d] + 1; t < next; ++t, ++kept)
      for (int i = 0; i < 3; ++i) mesh.indices[3 * kept + i] = mesh.indices[3 * t + i];
  }
  mesh.indices.resize(3 * kept);
  return drop.size();
}

}  // namespace marble
