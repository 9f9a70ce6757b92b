// optimizeDrawOrder changes only the order (the same triangles over the same points, each
// triangle's winding kept); simplifiedMesh collapses towards its target within its error
// bound, keeps only points of the original and keeps the winding outward, inside-out slivers
// wound back.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "dense_mesh.h"
#include "marble/mesh/closed_surface.h"
#include "marble/mesh/mesh_optimize.h"

using namespace marble;

namespace {

using Corner = std::tuple<float, float, float>;
using Triangle = std::array<Corner, 3>;

// Each triangle by its corners' positions, rotated so the smallest corner is first (the same
// triangle with the same winding compares equal whatever vertex it starts at), sorted.
std::vector<Triangle> triangleSet(const Mesh& m) {
  std::vector<Triangle> out;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    Triangle tri;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = m.positions[m.indices[t + k]];
      tri[k] = {p.x, p.y, p.z};
    }
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(OptimizeDrawOrder, SameTrianglesOtherOrder) {
  const Mesh original = builtinMesh("sculpture");
  Mesh m = original;
  optimizeDrawOrder(m);
  ASSERT_EQ(m.indices.size(), original.indices.size());
  ASSERT_EQ(m.positions.size(), original.positions.size());  // the sculpture uses every vertex
  ASSERT_EQ(m.normals.size(), m.positions.size());
  EXPECT_EQ(triangleSet(m), triangleSet(original));
  EXPECT_NE(m.indices, original.indices);  // it did reorder (negative control for the check above)
  // Vertices in first-use order: the first triangle is 0, 1, 2.
  EXPECT_EQ(m.indices[0], 0u);
  EXPECT_EQ(m.indices[1], 1u);
  EXPECT_EQ(m.indices[2], 2u);
  // Normals moved with their positions.
  for (size_t i = 0; i < original.positions.size(); ++i) {
    const auto it = std::find(m.positions.begin(), m.positions.end(), original.positions[i]);
    ASSERT_NE(it, m.positions.end());
    EXPECT_EQ(m.normals[static_cast<size_t>(it - m.positions.begin())], original.normals[i]);
  }
  EXPECT_NEAR(signedVolume(m), signedVolume(original), 1e-9 * std::abs(signedVolume(original)) + 1e-12);
}

TEST(OptimizeDrawOrder, MovedWindingIsCaught) {
  // The comparison above would notice a flipped triangle.
  Mesh m = builtinMesh("cube");
  const auto before = triangleSet(m);
  std::swap(m.indices[1], m.indices[2]);
  EXPECT_NE(triangleSet(m), before);
}

TEST(SimplifiedMesh, ReachesTargetWithinErrorAndKeepsShape) {
  const Mesh dense = marble::test::subdividedSmoothed(builtinMesh("sculpture"), 1);
  const SimplifiedMesh s = simplifiedMesh(dense, dense.triangleCount() / 4, 0.01f);
  EXPECT_LE(s.mesh.triangleCount(), dense.triangleCount() / 4 + dense.triangleCount() / 100);
  EXPECT_GT(s.mesh.triangleCount(), 1000u);
  EXPECT_LE(s.errorUnits, 0.01f);
  EXPECT_LT(s.mesh.positions.size(), dense.positions.size());  // compact
  // Every point of the copy is a point of the original (edge collapses move no vertex).
  std::vector<Corner> points;
  for (const glm::vec3& p : dense.positions) points.emplace_back(p.x, p.y, p.z);
  std::sort(points.begin(), points.end());
  for (const glm::vec3& p : s.mesh.positions)
    ASSERT_TRUE(std::binary_search(points.begin(), points.end(), Corner{p.x, p.y, p.z}));
  // Closed and outward: the enclosed volume is kept to within a few percent.
  EXPECT_NEAR(signedVolume(s.mesh), signedVolume(dense), 0.03 * signedVolume(dense));
}

TEST(SimplifiedMesh, ErrorCapBindsBeforeTheTarget) {
  const Mesh dense = marble::test::subdividedSmoothed(builtinMesh("sculpture"), 1);
  const SimplifiedMesh tight = simplifiedMesh(dense, 100, 1e-4f);
  const SimplifiedMesh loose = simplifiedMesh(dense, 100, 0.05f);
  EXPECT_LE(tight.errorUnits, 1e-4f);
  EXPECT_GT(tight.mesh.triangleCount(), 10 * loose.mesh.triangleCount());
}

TEST(SimplifiedMesh, AnInsideOutSliverIsWoundBack) {
  // A cube beside one 1 % of its size wound inward, as a collapse can leave one: the copy (with
  // nothing to collapse under a zero error bound) is closed one way round (orientSlivers).
  Mesh m = builtinMesh("cube");
  const Mesh small = builtinMesh("cube");
  const auto base = static_cast<uint32_t>(m.positions.size());
  for (const glm::vec3& p : small.positions) m.positions.push_back(p * 0.0099f + glm::vec3(2, 0, 0));
  m.normals.insert(m.normals.end(), small.normals.begin(), small.normals.end());
  for (size_t t = 0; t < small.triangleCount(); ++t)
    m.indices.insert(m.indices.end(), {base + small.indices[3 * t], base + small.indices[3 * t + 2], base + small.indices[3 * t + 1]});
  ASSERT_EQ(closedSurfaceWinding(m), SurfaceWinding::Open);
  const SimplifiedMesh s = simplifiedMesh(m, m.triangleCount(), 0.0f);
  EXPECT_EQ(s.mesh.triangleCount(), m.triangleCount());
  EXPECT_EQ(closedSurfaceWinding(s.mesh), SurfaceWinding::Outward);
}
