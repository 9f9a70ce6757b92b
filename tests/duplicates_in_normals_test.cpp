// removeDuplicatesAndComputeNormals (vertex_normals.h: the duplicate check done point by point in
// the normals' pass, loadMesh's path when a file has no normals) equals the two steps it replaces,
// removeDuplicateTriangles and then computeVertexNormals, bit for bit: positions, normals, texture
// coordinates, indices, and the count dropped. On meshes with duplicates by repetition, by
// rotation and under other vertex indices at the same positions; reversed windings (kept);
// triangles with a repeated point or without area repeated; an index out of range; points of a
// few corners (the small path) and of hundreds (the sorted path); and one large enough for threads.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <utility>

#include "marble/mesh/duplicate_triangles.h"
#include "marble/mesh/point_ids.h"
#include "marble/mesh/vertex_normals.h"

namespace marble {
namespace {

bool sameBits(const Mesh& a, const Mesh& b) {
  auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return same(a.positions, b.positions) && same(a.normals, b.normals) && same(a.texcoords, b.texcoords) &&
         same(a.indices, b.indices);
}

// The count dropped, and whether the one-pass result equals the two steps'.
std::pair<size_t, bool> compareWithTwoSteps(const Mesh& input, float crease) {
  Mesh twoSteps = input, onePass = input;
  const size_t expected = removeDuplicateTriangles(twoSteps, pointIds(twoSteps.positions));
  computeVertexNormals(twoSteps, crease, pointIds(twoSteps.positions));
  const size_t dropped = removeDuplicatesAndComputeNormals(onePass, crease, pointIds(onePass.positions));
  return {expected, dropped == expected && sameBits(onePass, twoSteps)};
}

void expectSameAsTwoSteps(const Mesh& input, const std::string& what, size_t atLeastDropped) {
  for (float crease : {kDefaultCreaseAngleDeg, 10.0f, kNoCreaseDeg}) {
    const auto [dropped, same] = compareWithTwoSteps(input, crease);
    EXPECT_TRUE(same) << what << ", crease " << crease;
    EXPECT_GE(dropped, atLeastDropped) << what << ": the mesh really has duplicates";
  }
}

// Triangles at random over a small lattice whose positions repeat under several vertex indices (-0
// for half the zeros): points of hundreds of corners, many duplicates (same and other indices,
// rotated), reversed copies, triangles with a repeated point, collinear ones without area.
Mesh latticeSoup(unsigned seed, size_t vertices, size_t triangles) {
  std::mt19937 rng(seed);
  Mesh m;
  for (size_t i = 0; i < vertices; ++i) {
    const float x = static_cast<float>(rng() % 3);
    m.positions.emplace_back(x == 0.0f && i % 2 ? -0.0f : x, static_cast<float>(rng() % 3), static_cast<float>(rng() % 2));
    m.texcoords.emplace_back(static_cast<float>(i), 0.25f);
  }
  for (size_t t = 0; t < 3 * triangles; ++t) m.indices.push_back(static_cast<uint32_t>(rng() % vertices));
  return m;
}

// A folded grid (points of ~6 corners: the small path) with 600 of its triangles repeated: as they
// are, rotated, reversed, and under a second set of vertices at the same positions; and a
// triangle with a repeated point, a collinear one without area, each repeated and rotated.
Mesh foldedGridWithRepeats(unsigned seed) {
  std::mt19937 rng(seed);
  Mesh m;
  const int n = 30;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) m.positions.emplace_back(x * 0.1f, y * 0.1f, static_cast<float>(rng() % 3) * 0.06f);
  const uint32_t copies = static_cast<uint32_t>(m.positions.size());
  for (uint32_t i = 0; i < copies; ++i) m.positions.push_back(m.positions[i]);  // the same positions again
  auto at = [&](int x, int y) { return static_cast<uint32_t>(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      m.indices.insert(m.indices.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y), at(x + 1, y + 1), at(x, y + 1)});
  const size_t triangles = m.indices.size() / 3;
  for (int i = 0; i < 600; ++i) {
    const size_t t = rng() % triangles;
    uint32_t v[3] = {m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]};
    const int r = static_cast<int>(rng() % 3);
    std::rotate(v, v + r, v + 3);
    if (i % 5 == 0) std::swap(v[1], v[2]);  // reversed: another triangle, kept
    if (i % 3 == 0)
      for (uint32_t& k : v) k += copies;  // other vertices, the same positions
    m.indices.insert(m.indices.end(), v, v + 3);
  }
  // Apart from the grid: a triangle with a repeated point (no part in the normals; its rotation is
  // its duplicate), a collinear one (three distinct points, no area: filed for the duplicate check
  // only; exact floats, so exactly collinear) and a flat one beside them, each repeated.
  const uint32_t p = static_cast<uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), {{5, 5, 0}, {5.5f, 5, 0}, {6, 5, 0}, {5, 6, 0}});
  m.positions.insert(m.positions.end(), {{5, 5, 0}, {5.5f, 5, 0}, {6, 5, 0}});  // p + 4 ... p + 6: the same again
  m.indices.insert(m.indices.end(), {p, p, p + 1, p, p + 1, p, p + 1, p, p});
  m.indices.insert(m.indices.end(), {p, p + 1, p + 2, p + 1, p + 2, p, p + 6, p + 4, p + 5, p, p + 2, p + 1});
  m.indices.insert(m.indices.end(), {p, p + 3, p + 1, p + 4, p + 3, p + 5});
  return m;
}

TEST(DuplicatesInNormals, FoldedGridWithRepeatsEqualsTheTwoSteps) {
  for (unsigned seed : {1u, 2u}) expectSameAsTwoSteps(foldedGridWithRepeats(seed), "folded grid " + std::to_string(seed), 300);
}

TEST(DuplicatesInNormals, LatticeSoupsEqualTheTwoSteps) {
  for (unsigned seed : {1u, 2u, 3u}) expectSameAsTwoSteps(latticeSoup(seed, 60, 3000), "soup " + std::to_string(seed), 1000);
}

// 150,000 triangles: the triangles and the points are split over threads (on two or more cores).
TEST(DuplicatesInNormals, ThreadedSoupEqualsTheTwoSteps) {
  Mesh m = latticeSoup(9, 40000, 150000);
  expectSameAsTwoSteps(m, "150k-triangle soup", 1000);
}

// The records written into memory handed over (loadMesh hands over the file's bytes) instead of
// fresh pages: the same mesh, whatever the memory held and whatever its size; the memory used.
TEST(DuplicatesInNormals, RecycledMemoryGivesTheSameMesh) {
  for (const Mesh& input : {foldedGridWithRepeats(3), latticeSoup(4, 60, 3000)})
    for (size_t bytes : {size_t{0}, size_t{100}, size_t{1} << 20})
      for (int pattern : {0x00, 0x5A, 0xFF}) {
        Mesh fresh = input, recycledInto = input;
        PageBuffer memory(bytes);
        if (bytes) std::memset(memory.data(), pattern, bytes);
        const size_t expected = removeDuplicatesAndComputeNormals(fresh, kDefaultCreaseAngleDeg, pointIds(fresh.positions));
        const size_t dropped =
            removeDuplicatesAndComputeNormals(recycledInto, kDefaultCreaseAngleDeg, pointIds(recycledInto.positions), &memory);
        EXPECT_EQ(dropped, expected);
        EXPECT_TRUE(sameBits(recycledInto, fresh)) << bytes << " bytes of " << pattern;
        EXPECT_GE(memory.size(), input.indices.size() / 3 * 48) << "the records went into the memory handed over";
      }
}

// An index out of range (possible only through the API: loadMesh checks them first) is its own
// point to both steps; the triangle and its rotation are one.
TEST(DuplicatesInNormals, IndexOutOfRangeEqualsTheTwoSteps) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.indices = {0, 1, 2, 0, 9, 3, 9, 3, 0, 1, 2, 0, 0, 2, 3};
  const auto [dropped, same] = compareWithTwoSteps(m, kDefaultCreaseAngleDeg);
  EXPECT_TRUE(same);
  EXPECT_EQ(dropped, 2u);
}

}  // namespace
}  // namespace marble
