// computeVertexNormals (hashed points, edges bucketed by point, triangles over threads) equals the
// first, sort-based implementation (vertex_normals_reference.h) bit for bit: normals, positions,
// indices and texture coordinates, on meshes that exercise every rule (shared positions, +0 and -0,
// creases, edges with 1 or 3+ triangles, flipped winding, degenerate triangles, a point with
// hundreds of edges).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "marble/mesh/vertex_normals.h"
#include "vertex_normals_reference.h"

namespace marble {
namespace {

bool bitEqual(const Mesh& a, const Mesh& b) {
  auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return same(a.positions, b.positions) && same(a.normals, b.normals) && same(a.texcoords, b.texcoords) &&
         a.indices == b.indices;
}

// A soup on a coarse lattice: many triangles share positions through different vertex indices, edges
// have 1-5 triangles in either direction, some triangles are degenerate, half the zeros are -0.
Mesh latticeSoup(unsigned seed, size_t vertices, size_t triangles) {
  std::mt19937 rng(seed);
  Mesh m;
  for (size_t i = 0; i < vertices; ++i) {
    const float z = static_cast<float>(rng() % 3) * 0.5f;
    m.positions.emplace_back(static_cast<float>(rng() % 7) * 0.5f - 1.5f, static_cast<float>(rng() % 5) * 0.5f,
                             (i % 2 && z == 0.0f) ? -0.0f : z);
    m.texcoords.emplace_back(static_cast<float>(i) / static_cast<float>(vertices), 0.5f);
  }
  for (size_t t = 0; t < 3 * triangles; ++t) m.indices.push_back(static_cast<uint32_t>(rng() % vertices));
  return m;
}

// One point at the centre of a 400-triangle fan (its bucket is sorted by std::sort, not by the
// insertion sort the small buckets get), every other spoke folded by 70 degrees.
Mesh foldedFan() {
  Mesh m;
  m.positions.emplace_back(0.0f, 0.0f, 0.0f);
  const int spokes = 400;
  for (int i = 0; i < spokes; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / spokes;
    m.positions.emplace_back(std::cos(a), std::sin(a), i % 2 ? 0.0f : 1.4f);
  }
  for (int i = 0; i < spokes; ++i) m.indices.insert(m.indices.end(), {0u, 1u + i, 1u + (i + 1) % spokes});
  return m;
}

void expectSameAsReference(const Mesh& input, float crease, const char* what) {
  Mesh fast = input, reference = input;
  computeVertexNormals(fast, crease);
  reference::computeVertexNormalsBySorting(reference, crease);
  EXPECT_TRUE(bitEqual(fast, reference)) << what << ", crease " << crease;
}

TEST(VertexNormalsEquivalence, BuiltinMeshesEqualTheSortedReference) {
  for (const std::string& name : builtinMeshNames()) {
    Mesh m = builtinMesh(name);
    m.normals.clear();
    for (float crease : {kDefaultCreaseAngleDeg, 30.0f, kNoCreaseDeg}) expectSameAsReference(m, crease, name.c_str());
  }
}

TEST(VertexNormalsEquivalence, SoupsAndFansEqualTheSortedReference) {
  for (unsigned seed : {1u, 2u, 3u})
    for (float crease : {kDefaultCreaseAngleDeg, 10.0f, kNoCreaseDeg})
      expectSameAsReference(latticeSoup(seed, 3000, 20000), crease, "lattice soup");
  for (float crease : {kDefaultCreaseAngleDeg, 80.0f, kNoCreaseDeg}) expectSameAsReference(foldedFan(), crease, "folded fan");
  // Only degenerate triangles: no edge is used at all (found by fuzz_obj under UBSan: an empty
  // bucket array's null data() must not be offset).
  Mesh degenerate;
  degenerate.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}};
  degenerate.indices = {0, 1, 0, 2, 2, 1};
  for (float crease : {kDefaultCreaseAngleDeg, kNoCreaseDeg}) expectSameAsReference(degenerate, crease, "degenerate only");
  // A point whose first corner (in file order) is on a zero-area triangle with three distinct
  // points (collinear): filed under the point but taking no part, so the fan's first corner is
  // the next one (the no-crease path picks it explicitly).
  Mesh collinear;
  collinear.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  collinear.indices = {0, 1, 2, 0, 1, 3, 0, 3, 4, 0, 4, 1};
  for (float crease : {kDefaultCreaseAngleDeg, kNoCreaseDeg}) expectSameAsReference(collinear, crease, "collinear first");
}

// Large enough (150,000 triangles) that the triangles and the points are split over threads (two
// or more parts on a machine with two or more cores).
TEST(VertexNormalsEquivalence, ThreadedMeshEqualsTheSortedReference) {
  expectSameAsReference(latticeSoup(7, 40000, 150000), kDefaultCreaseAngleDeg, "150k-triangle soup");
}

// Negative control: the comparison sees a different crease angle's result (it can fail).
TEST(VertexNormalsEquivalence, ComparisonDetectsADifferentCrease) {
  Mesh input = builtinMesh("cube");
  input.normals.clear();
  Mesh a = input, b = input;
  computeVertexNormals(a, kDefaultCreaseAngleDeg);
  reference::computeVertexNormalsBySorting(b, kNoCreaseDeg);
  EXPECT_FALSE(bitEqual(a, b));
}

}  // namespace
}  // namespace marble
