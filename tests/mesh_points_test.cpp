// Points (point_ids.h) and the two steps that share them in loadMesh: the duplicate-triangle
// check by points equals the check by corner positions it replaced, and loadMesh judges
// duplicates on the normalized positions (the positions drawn, and the normals' points).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "temp_dir.h"
#include "marble/mesh/duplicate_triangles.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/point_ids.h"

namespace marble {
namespace {

TEST(PointIds, EqualPositionsShareTheLowestIndex) {
  const float up = std::nextafter(1.0f, 2.0f);
  const std::vector<glm::vec3> positions = {{1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {-0.0f, 0, -0.0f}, {up, 0, 0}, {0, 1, 0}};
  // -0 is +0; a position one float step away is its own point (negative control).
  EXPECT_EQ(pointIds(positions), (std::vector<uint32_t>{0, 1, 0, 1, 4, 5}));
  EXPECT_TRUE(pointIds({}).empty());
}

// Points by their definition: per vertex the lowest index at its position's bits (-0 as +0).
std::vector<uint32_t> pointIdsByMap(const std::vector<glm::vec3>& positions) {
  auto word = [](float f) { return f == 0.0f ? 0u : std::bit_cast<uint32_t>(f); };
  std::map<std::array<uint32_t, 3>, uint32_t> first;
  std::vector<uint32_t> id;
  for (size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3 p = positions[i];
    id.push_back(first.try_emplace({word(p.x), word(p.y), word(p.z)}, static_cast<uint32_t>(i)).first->second);
  }
  return id;
}

TEST(PointIds, TheIdsDoNotDependOnTheNumberOfTables) {
  // 300,000 vertices (several ranges of the hashing passes) at 40,000 lattice positions, half the
  // zeros -0: each position repeated under indices spread over the whole array. Split over tables
  // (one thread each, by hash), the lowest index at each position must still win.
  std::mt19937 rng(7);
  std::vector<glm::vec3> positions;
  for (int i = 0; i < 300000; ++i) {
    const float x = static_cast<float>(rng() % 200) - 100.0f, y = static_cast<float>(rng() % 200);
    positions.emplace_back(x == 0.0f && i % 2 ? -0.0f : x, y, y == 0.0f && i % 3 ? -0.0f : 0.5f);
  }
  const std::vector<uint32_t> expected = pointIdsByMap(positions);
  for (unsigned tables : {0u, 1u, 2u, 3u, 4u, 7u}) EXPECT_EQ(pointIds(positions, tables), expected) << tables << " tables";
}

// The duplicate check by its definition (duplicate_triangles.h): corners compared by their
// positions' bits (-0 as +0), the three rotations one triangle (keyed by the smallest), the first
// of each kept; a std::set, straightforward.
std::vector<uint32_t> withoutDuplicatesByPositions(const Mesh& m, bool rotations = true) {
  using Corner = std::array<uint32_t, 3>;
  auto bits = [](glm::vec3 p) {
    auto word = [](float f) { return f == 0.0f ? 0u : std::bit_cast<uint32_t>(f); };
    return Corner{word(p.x), word(p.y), word(p.z)};
  };
  std::set<std::array<Corner, 3>> seen;
  std::vector<uint32_t> kept;
  for (size_t t = 0; t < m.indices.size() / 3; ++t) {
    std::array<Corner, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = bits(m.positions[m.indices[3 * t + k]]);
    std::array<Corner, 3> key = c;
    if (rotations) key = std::min({c, {c[1], c[2], c[0]}, {c[2], c[0], c[1]}});
    if (!seen.insert(key).second) continue;
    kept.insert(kept.end(), {m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]});
  }
  return kept;
}

// Triangles on a 3x3x2 lattice with positions repeated under several indices and half the zeros
// -0: many exact duplicates, by rotation and under other indices, and many reversed windings.
Mesh duplicateSoup(unsigned seed) {
  std::mt19937 rng(seed);
  Mesh m;
  for (int i = 0; i < 60; ++i) {
    const float x = static_cast<float>(rng() % 3), z = static_cast<float>(rng() % 2);
    m.positions.emplace_back(x == 0.0f && i % 2 ? -0.0f : x, static_cast<float>(rng() % 3), z);
  }
  for (int t = 0; t < 3000; ++t)
    for (int k = 0; k < 3; ++k) m.indices.push_back(static_cast<uint32_t>(rng() % m.positions.size()));
  return m;
}

TEST(PointIds, DuplicateCheckByPointsEqualsTheCheckByPositions) {
  for (unsigned seed : {1u, 2u, 3u}) {
    Mesh m = duplicateSoup(seed);
    const std::vector<uint32_t> expected = withoutDuplicatesByPositions(m);
    const size_t removed = removeDuplicateTriangles(m, pointIds(m.positions));
    EXPECT_GT(removed, 1000u) << "seed " << seed;  // the soup really has duplicates
    EXPECT_EQ(m.indices, expected) << "seed " << seed;
  }
}

TEST(PointIds, DuplicateCheckDoesNotDependOnTheNumberOfTables) {
  // Split over tables (one thread each, by hash), each key's first triangle must still be kept:
  // 1 to 7 tables against the std::set check, on soups whose duplicates are spread over the file.
  for (unsigned seed : {4u, 5u})
    for (unsigned tables : {1u, 2u, 3u, 4u, 7u}) {
      Mesh m = duplicateSoup(seed);
      const std::vector<uint32_t> expected = withoutDuplicatesByPositions(m);
      const size_t removed = removeDuplicateTriangles(m, pointIds(m.positions), tables);
      EXPECT_GT(removed, 1000u) << "seed " << seed << ", " << tables << " tables";
      EXPECT_EQ(m.indices, expected) << "seed " << seed << ", " << tables << " tables";
    }
}

TEST(PointIds, DuplicateComparisonDetectsAMissedRotation) {
  // Negative control: a check that ignored rotations keeps other triangles, and the comparison
  // above sees it.
  const Mesh m = duplicateSoup(1);
  EXPECT_NE(withoutDuplicatesByPositions(m, false), withoutDuplicatesByPositions(m, true));
}

TEST(PointIds, LoadMeshJudgesDuplicatesAfterNormalization) {
  // Two triangles whose first corners differ by one float step at x = 1; a far vertex makes the
  // extent 3e6, so normalization (a scale of 2 / 3e6) rounds both corners to one position.
  const marble::test::TempDir dir("points");
  const auto file = dir / "near.obj";
  std::ofstream(file) << "v 1 0 0\nv 1.00000012 0 0\nv 0 1 0\nv 0 0 1\nv 3000000 0 0\nf 1 3 4\nf 2 3 4\n";
  std::vector<std::string> warnings;
  MeshLoadOptions options;
  options.warnings = &warnings;
  const Mesh loaded = loadMesh(file, options);
  ASSERT_EQ(loaded.positions.size(), 5u);
  ASSERT_EQ(loaded.positions[0], loaded.positions[1]);  // the premise: the scale merged them
  EXPECT_EQ(loaded.triangleCount(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("dropped 1 duplicate"), std::string::npos);
  // Negative control: before normalization the two are different triangles.
  Mesh raw;
  raw.positions = {{1, 0, 0}, {std::nextafter(1.0f, 2.0f), 0, 0}, {0, 1, 0}, {0, 0, 1}, {3e6f, 0, 0}};
  raw.indices = {0, 2, 3, 1, 2, 3};
  EXPECT_EQ(removeDuplicateTriangles(raw), 0u);
}

}  // namespace
}  // namespace marble
