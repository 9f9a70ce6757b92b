#include "marble/mesh/point_ids.h"

#include <bit>

#include "marble/core/parallel_for.h"

namespace marble {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;

uint64_t positionHash(glm::vec3 p) {
  auto word = [](float f) { return f == 0.0f ? 0u : std::bit_cast<uint32_t>(f); };  // -0 -> +0
  uint64_t h = (static_cast<uint64_t>(word(p.x)) << 32 | word(p.y)) * 0x9E3779B97F4A7C15ull;
  h = (h ^ word(p.z) ^ (h >> 31)) * 0xBF58476D1CE4E5B9ull;
  return h ^ (h >> 29);
}

}  // namespace

std::vector<uint32_t> pointIds(const std::vector<glm::vec3>& positions) {
  const size_t n = positions.size();
  size_t capacity = 16;
  while (capacity < 2 * n) capacity *= 2;  // load factor <= 1/2
  const size_t mask = capacity - 1;
  // The slots first, over threads; then the table filled in vertex order (the lowest index at a
  // position must win), the slot of a vertex a few ahead prefetched: the table is far larger than
  // the caches, and a miss per vertex was most of the time.
  std::vector<uint32_t> id(n);
  parallelFor(n, 100000, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) id[i] = static_cast<uint32_t>(positionHash(positions[i]) & mask);
  });
  std::vector<uint32_t> slots(capacity, kNone);  // a vertex index: the first at its position
  constexpr size_t kAhead = 8;
  for (uint32_t i = 0; i < n; ++i) {
    if (i + kAhead < n) __builtin_prefetch(&slots[id[i + kAhead]]);
    const glm::vec3 p = positions[i];
    for (size_t slot = id[i];; slot = (slot + 1) & mask) {
      const uint32_t k = slots[slot];
      if (k == kNone) {
        slots[slot] = i;
        id[i] = i;
        break;
      }
      if (positions[k] == p) {
        id[i] = k;
        break;
      }
    }
  }
  return id;
}

}  // namespace marble
