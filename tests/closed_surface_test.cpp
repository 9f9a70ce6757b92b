// closedSurfaceWinding (mesh/closed_surface.h): what lets the camera's pass cull the faces turned
// away from it (render/face_culling.h), so every way a mesh can fail to bound a solid one way
// round must come out Open.
// Negative controls (by hand, session 22): without the parts' volume-sign test,
// PartsWoundDifferentWaysOpenIt fails; with an edge accepted where its reverse exists at all (not
// exactly once each way), AnEdgeOfFourTrianglesOpensIt fails.
#include <gtest/gtest.h>

#include <algorithm>

#include "marble/mesh/closed_surface.h"
#include "marble/mesh/mesh.h"

namespace marble {
namespace {

Mesh reversed(Mesh m) {
  for (size_t t = 0; t < m.triangleCount(); ++t) std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]);
  return m;
}

// Two meshes as one (the second's indices moved past the first's vertices), b moved by offset.
Mesh joined(const Mesh& a, Mesh b, glm::vec3 offset) {
  Mesh m = a;
  const auto base = static_cast<uint32_t>(a.positions.size());
  for (glm::vec3& p : b.positions) p += offset;
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  m.normals.insert(m.normals.end(), b.normals.begin(), b.normals.end());
  for (uint32_t i : b.indices) m.indices.push_back(base + i);
  return m;
}

TEST(ClosedSurface, TheCubeOfFourVerticesPerFaceIsClosedOutward) {
  // 24 vertices: each corner is three vertices (one per face's normal), one point.
  const Mesh cube = builtinMesh("cube");
  ASSERT_EQ(cube.positions.size(), 24u);
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Outward);
  EXPECT_EQ(closedSurfaceWinding(reversed(cube)), SurfaceWinding::Inward);
}

TEST(ClosedSurface, TheSculptureAndTheTorusAreClosedOutward) {
  EXPECT_EQ(closedSurfaceWinding(builtinMesh("sculpture")), SurfaceWinding::Outward);
  EXPECT_EQ(closedSurfaceWinding(builtinMesh("torus")), SurfaceWinding::Outward);
}

TEST(ClosedSurface, AHoleOpensIt) {
  Mesh cube = builtinMesh("cube");
  cube.indices.resize(cube.indices.size() - 3);
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Open);
}

TEST(ClosedSurface, OneTriangleWoundTheOtherWayOpensIt) {
  Mesh cube = builtinMesh("cube");
  std::swap(cube.indices[1], cube.indices[2]);
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Open);
}

TEST(ClosedSurface, ATriangleWithTwoCornersAtOnePointOpensIt) {
  Mesh cube = builtinMesh("cube");
  cube.positions.push_back(cube.positions[cube.indices[0]]);  // another vertex at a corner's point
  const auto copy = static_cast<uint32_t>(cube.positions.size() - 1);
  cube.indices.insert(cube.indices.end(), {cube.indices[0], copy, cube.indices[1]});
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Open);
}

TEST(ClosedSurface, PartsWoundDifferentWaysOpenIt) {
  const Mesh cube = builtinMesh("cube");
  EXPECT_EQ(closedSurfaceWinding(joined(cube, cube, glm::vec3(5, 0, 0))), SurfaceWinding::Outward);
  EXPECT_EQ(closedSurfaceWinding(joined(reversed(cube), reversed(cube), glm::vec3(5, 0, 0))), SurfaceWinding::Inward);
  // An inward part beside an outward one: seen from outside, its turned-away faces come first.
  EXPECT_EQ(closedSurfaceWinding(joined(cube, reversed(cube), glm::vec3(5, 0, 0))), SurfaceWinding::Open);
}

TEST(ClosedSurface, AnEdgeOfThreeTrianglesOpensIt) {
  Mesh cube = builtinMesh("cube");
  // A fin on the cube: a triangle on an existing edge (its first triangle's first two corners).
  cube.positions.push_back(glm::vec3(3, 3, 3));
  const auto tip = static_cast<uint32_t>(cube.positions.size() - 1);
  cube.indices.insert(cube.indices.end(), {cube.indices[0], cube.indices[1], tip});
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Open);
}

TEST(ClosedSurface, AnEdgeOfFourTrianglesOpensIt) {
  // A fin of two triangles wound against each other on an edge of the cube: every edge is used as
  // often each way, but the cube's edge four times. Taken as Open (only two triangles an edge are
  // accepted), though the fin alone, of no volume, would not break the culling's argument.
  Mesh cube = builtinMesh("cube");
  cube.positions.push_back(glm::vec3(3, 3, 3));
  const auto tip = static_cast<uint32_t>(cube.positions.size() - 1);
  const uint32_t a = cube.indices[0], b = cube.indices[1];
  cube.indices.insert(cube.indices.end(), {a, b, tip, b, a, tip});
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Open);
}

TEST(ClosedSurface, NoTrianglesIsOpen) { EXPECT_EQ(closedSurfaceWinding(Mesh{}), SurfaceWinding::Open); }

}  // namespace
}  // namespace marble
