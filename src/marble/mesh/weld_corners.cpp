#include "marble/mesh/weld_corners.h"

#include <algorithm>
#include <bit>

#include "marble/core/parallel_for.h"

namespace marble::mesh_detail {
namespace {

constexpr uint32_t kEmpty = 0xFFFFFFFFu;

bool sameBits(const glm::vec3& a, const glm::vec3& b) {
  return std::bit_cast<uint32_t>(a.x) == std::bit_cast<uint32_t>(b.x) &&
         std::bit_cast<uint32_t>(a.y) == std::bit_cast<uint32_t>(b.y) &&
         std::bit_cast<uint32_t>(a.z) == std::bit_cast<uint32_t>(b.z);
}

uint64_t hashOf(const glm::vec3& p) {
  const uint64_t bx = std::bit_cast<uint32_t>(p.x), by = std::bit_cast<uint32_t>(p.y), bz = std::bit_cast<uint32_t>(p.z);
  const uint64_t h = bx * 0x9E3779B97F4A7C15ull ^ by * 0xC2B2AE3D27D4EB4Full ^ bz * 0x165667B19E3779F9ull;
  return h ^ (h >> 31);
}

// Below this many corners per thread a thread's start costs more than it saves.
constexpr size_t kCornersPerThread = 1u << 16;

}  // namespace

WeldedCorners weldCorners(std::vector<glm::vec3> corners, unsigned threads) {
  const size_t n = corners.size();
  if (threads == 0) threads = workerThreadCount(n, kCornersPerThread);
  threads = std::max(1u, threads);

  // Pass 1: -0 -> +0 (so they weld) and each corner's hash; the part is the hash's top bits.
  std::vector<uint64_t> hashes(n);
  parallelFor(n, kCornersPerThread, [&](size_t first, size_t last) {
    for (size_t c = first; c < last; ++c) {
      glm::vec3& p = corners[c];
      if (p.x == 0.0f) p.x = 0.0f;
      if (p.y == 0.0f) p.y = 0.0f;
      if (p.z == 0.0f) p.z = 0.0f;
      hashes[c] = hashOf(p);
    }
  });
  auto partOf = [threads](uint64_t h) { return static_cast<unsigned>(((h >> 32) * threads) >> 32); };

  // Pass 2: firstEqual[c] = the first corner with c's position. One part of the hash space per
  // thread, each with its own open-addressing table (load factor <= 1/2) of first corners.
  std::vector<uint32_t> firstEqual(n);
  auto weldPart = [&](unsigned part) {
    size_t members = 0;
    for (size_t c = 0; c < n; ++c) members += partOf(hashes[c]) == part;
    size_t capacity = 16;
    while (capacity < members * 2) capacity *= 2;
    std::vector<uint32_t> slots(capacity, kEmpty);
    const size_t mask = capacity - 1;
    for (size_t c = 0; c < n; ++c) {
      const uint64_t h = hashes[c];
      if (partOf(h) != part) continue;
      for (size_t slot = static_cast<size_t>(h) & mask;; slot = (slot + 1) & mask) {
        const uint32_t seen = slots[slot];
        if (seen == kEmpty) {
          slots[slot] = static_cast<uint32_t>(c);
          firstEqual[c] = static_cast<uint32_t>(c);
          break;
        }
        if (sameBits(corners[seen], corners[c])) {
          firstEqual[c] = seen;
          break;
        }
      }
    }
  };
  parallelFor(threads, 1, [&](size_t first, size_t last) {
    for (size_t part = first; part < last; ++part) weldPart(static_cast<unsigned>(part));
  });

  // Pass 3: vertices numbered in the order of their first corners.
  WeldedCorners out;
  out.indices.resize(n);
  for (size_t c = 0; c < n; ++c) {
    const uint32_t f = firstEqual[c];
    if (f == c) {
      out.indices[c] = static_cast<uint32_t>(out.positions.size());
      out.positions.push_back(corners[c]);
    } else {
      out.indices[c] = out.indices[f];
    }
  }
  return out;
}

}  // namespace marble::mesh_detail
