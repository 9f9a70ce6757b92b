#include "marble/mesh/point_ids.h"

#include <algorithm>
#include <bit>
#include <memory>

#include "marble/core/parallel_for.h"

namespace marble {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;
// Vertices per range of the hashing passes, and per table: below this a thread costs more than it saves.
constexpr size_t kVerticesPerThread = 100000;
// The slot of a vertex a few ahead is prefetched in the fill: the table is far larger than the
// caches, and a miss per vertex was most of the time.
constexpr size_t kAhead = 8;

uint64_t positionHash(glm::vec3 p) {
  auto word = [](float f) { return f == 0.0f ? 0u : std::bit_cast<uint32_t>(f); };  // -0 -> +0
  uint64_t h = (static_cast<uint64_t>(word(p.x)) << 32 | word(p.y)) * 0x9E3779B97F4A7C15ull;
  h = (h ^ word(p.z) ^ (h >> 31)) * 0xBF58476D1CE4E5B9ull;
  return h ^ (h >> 29);
}

// One table, open addressing with linear probing, load factor <= 1/2, filled in ascending vertex
// order: a vertex's point is the first vertex inserted at its position.
class PointTable {
public:
  PointTable(const std::vector<glm::vec3>& positions, size_t entries)
      : positions_(positions), slots_(tableCapacity(entries), kNone), mask_(slots_.size() - 1) {}
  void prefetch(uint32_t hash) const { __builtin_prefetch(&slots_[hash & mask_]); }
  // Vertex i's point (i itself when it is the first at its position); `hash` is its hash's low bits.
  uint32_t pointOf(uint32_t i, uint32_t hash) {
    const glm::vec3 p = positions_[i];
    for (size_t slot = hash & mask_;; slot = (slot + 1) & mask_) {
      const uint32_t k = slots_[slot];
      if (k == kNone) {
        slots_[slot] = i;
        return i;
      }
      if (positions_[k] == p) return k;
    }
  }

private:
  static size_t tableCapacity(size_t entries) {
    size_t capacity = 16;
    while (capacity < 2 * entries) capacity *= 2;
    return capacity;
  }
  const std::vector<glm::vec3>& positions_;
  std::vector<uint32_t> slots_;  // a vertex index: the first at its position
  size_t mask_;
};

}  // namespace

std::vector<uint32_t> pointIds(const std::vector<glm::vec3>& positions, unsigned tables) {
  const size_t n = positions.size();
  tables = tables == 0 ? workerThreadCount(n, kVerticesPerThread, 4) : std::min(tables, 255u);  // a byte per vertex
  std::vector<uint32_t> id(n);
  if (tables <= 1) {
    // The hashes first, over threads; then the one table filled in vertex order.
    parallelFor(n, kVerticesPerThread, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) id[i] = static_cast<uint32_t>(positionHash(positions[i]));
    });
    PointTable points(positions, n);
    for (uint32_t i = 0; i < n; ++i) {
      if (i + kAhead < n) points.prefetch(id[i + kAhead]);
      id[i] = points.pointOf(i, id[i]);
    }
    return id;
  }
  // Several tables, one thread each, no locks: a vertex's table is its hash's top bits, so all
  // vertices at one position meet in one table, and each table is filled in vertex order, so the
  // lowest index at a position wins whatever the number of tables (the one-table result).
  // 1. Over ranges of vertices: each vertex's hash, and per range and table its vertices in order.
  auto tableOf = [tables](uint64_t h) { return static_cast<unsigned>(((h >> 32) * tables) >> 32); };
  const unsigned ranges = workerThreadCount(n, kVerticesPerThread);
  const std::unique_ptr<uint32_t[]> slotHash = std::make_unique_for_overwrite<uint32_t[]>(n);
  const std::unique_ptr<uint8_t[]> table = std::make_unique_for_overwrite<uint8_t[]>(n);
  std::vector<std::vector<std::vector<uint32_t>>> listed(ranges, std::vector<std::vector<uint32_t>>(tables));
  parallelFor(ranges, 1, [&](size_t first, size_t last) {
    for (size_t r = first; r < last; ++r) {
      const size_t begin = n * r / ranges, end = n * (r + 1) / ranges;
      for (std::vector<uint32_t>& l : listed[r]) l.reserve((end - begin) / tables + (end - begin) / 16 + 16);
      for (size_t i = begin; i < end; ++i) {
        const uint64_t h = positionHash(positions[i]);
        slotHash[i] = static_cast<uint32_t>(h);
        table[i] = static_cast<uint8_t>(tableOf(h));
        listed[r][table[i]].push_back(static_cast<uint32_t>(i));
      }
    }
  });
  // 2. Each table on its own thread, its vertices in order (the ranges in order); each list entry
  //    becomes its vertex's point (written in place: the threads share no output cache lines).
  parallelFor(tables, 1, [&](size_t first, size_t last) {
    for (size_t t = first; t < last; ++t) {
      size_t entries = 0;
      for (unsigned r = 0; r < ranges; ++r) entries += listed[r][t].size();
      PointTable points(positions, entries);
      for (unsigned r = 0; r < ranges; ++r) {
        std::vector<uint32_t>& list = listed[r][t];
        for (size_t j = 0; j < list.size(); ++j) {
          if (j + kAhead < list.size()) points.prefetch(slotHash[list[j + kAhead]]);
          list[j] = points.pointOf(list[j], slotHash[list[j]]);
        }
      }
    }
  });
  // 3. Over ranges again: each vertex's point from its table's list, in order.
  parallelFor(ranges, 1, [&](size_t first, size_t last) {
    for (size_t r = first; r < last; ++r) {
      std::vector<size_t> next(tables, 0);
      for (size_t i = n * r / ranges, end = n * (r + 1) / ranges; i < end; ++i) id[i] = listed[r][table[i]][next[table[i]]++];
    }
  });
  return id;
}

}  // namespace marble
