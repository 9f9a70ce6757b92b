// closedSurfaceWinding (mesh/closed_surface.h): what lets the camera's pass cull the faces turned
// away from it (render/face_culling.h), so every way a mesh can fail to bound a solid one way
// round must come out Open.
// Negative controls (by hand, session 22): without the parts' volume-sign test,
// PartsWoundDifferentWaysOpenIt fails; with an edge accepted where its reverse exists at all (not
// as often), AnEdgeUsedTwiceOneWayAndOnceTheOtherOpensIt fails.
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

TEST(ClosedSurface, ATriangleWithTwoCornersAtOnePointIsLeftOut) {
  // It covers nothing and crosses nothing, and its edges (a loop, and one edge each way) would
  // otherwise count.
  Mesh cube = builtinMesh("cube");
  cube.positions.push_back(cube.positions[cube.indices[0]]);  // another vertex at a corner's point
  const auto copy = static_cast<uint32_t>(cube.positions.size() - 1);
  cube.indices.insert(cube.indices.end(), {cube.indices[0], copy, cube.indices[1]});
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Outward);
}

TEST(ClosedSurface, PartsWoundDifferentWaysOpenIt) {
  const Mesh cube = builtinMesh("cube");
  EXPECT_EQ(closedSurfaceWinding(joined(cube, cube, glm::vec3(5, 0, 0))), SurfaceWinding::Outward);
  EXPECT_EQ(closedSurfaceWinding(joined(reversed(cube), reversed(cube), glm::vec3(5, 0, 0))), SurfaceWinding::Inward);
  // An inward part beside an outward one: seen from outside, its turned-away faces come first.
  EXPECT_EQ(closedSurfaceWinding(joined(cube, reversed(cube), glm::vec3(5, 0, 0))), SurfaceWinding::Open);
}

TEST(ClosedSurface, AnEdgeUsedTwiceOneWayAndOnceTheOtherOpensIt) {
  // A triangle on an edge of the cube and another closing it off on one side only.
  Mesh cube = builtinMesh("cube");
  cube.positions.push_back(glm::vec3(3, 3, 3));
  const auto tip = static_cast<uint32_t>(cube.positions.size() - 1);
  const uint32_t a = cube.indices[0], b = cube.indices[1];
  cube.indices.insert(cube.indices.end(), {a, b, tip});
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Open);
  // Its twin wound the other way makes the edge one of four, as often each way: closed (a fin of
  // no volume, which no ray crosses into anything).
  cube.indices.insert(cube.indices.end(), {b, a, tip});
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Outward);
  // The first one again: every edge still has its reverse, but three uses against two.
  cube.indices.insert(cube.indices.end(), {a, b, tip});
  EXPECT_EQ(closedSurfaceWinding(cube), SurfaceWinding::Open);
}

TEST(ClosedSurface, TwoCubesSharingAnEdgeAreClosed) {
  // Parts that touch along an edge (as a simplified copy's do): the edge is used twice each way.
  const Mesh cube = builtinMesh("cube");
  EXPECT_EQ(closedSurfaceWinding(joined(cube, cube, glm::vec3(2, 2, 0))), SurfaceWinding::Outward);
}

Mesh scaled(Mesh m, float factor) {
  for (glm::vec3& p : m.positions) p *= factor;
  return m;
}

TEST(ClosedSurface, ASliverWoundTheOtherWayIsTurnedToTheLargestPartsSense) {
  // The cube [-1, 1]^3 (volume 8) and a detached cube of half-size 0.01 (8e-6, the fraction's
  // limit), then 0.0101, wound inward at x = 2.
  const Mesh cube = builtinMesh("cube");
  const glm::vec3 beside(2.0f, 0.0f, 0.0f);
  Mesh m = joined(cube, reversed(scaled(cube, 0.0099f)), beside);
  EXPECT_EQ(closedSurfaceWinding(m), SurfaceWinding::Open);
  EXPECT_EQ(orientSlivers(m), 1u);
  EXPECT_EQ(closedSurfaceWinding(m), SurfaceWinding::Outward);
  EXPECT_EQ(m.indices, joined(cube, scaled(cube, 0.0099f), beside).indices);  // only the sliver's triangles turned
  EXPECT_EQ(orientSlivers(m), 0u);
  // The other way round; and the largest part decides wherever it is in the list.
  Mesh inward = joined(reversed(cube), scaled(cube, 0.0099f), beside);
  EXPECT_EQ(orientSlivers(inward), 1u);
  EXPECT_EQ(closedSurfaceWinding(inward), SurfaceWinding::Inward);
  Mesh first = joined(reversed(scaled(cube, 0.0099f)), cube, beside);
  EXPECT_EQ(orientSlivers(first), 1u);
  EXPECT_EQ(closedSurfaceWinding(first), SurfaceWinding::Outward);
  // Larger than a sliver: a part wound against the rest on purpose (or a cavity) stays as it is.
  Mesh part = joined(cube, reversed(scaled(cube, 0.0101f)), beside);
  EXPECT_EQ(orientSlivers(part), 0u);
  EXPECT_EQ(closedSurfaceWinding(part), SurfaceWinding::Open);
  // Parts of the same sense, and a mesh of one part, are left alone.
  Mesh same = joined(cube, scaled(cube, 0.0099f), beside);
  EXPECT_EQ(orientSlivers(same), 0u);
  Mesh one = reversed(cube);
  EXPECT_EQ(orientSlivers(one), 0u);
  EXPECT_EQ(closedSurfaceWinding(one), SurfaceWinding::Inward);
}

TEST(ClosedSurface, NoTrianglesIsOpen) { EXPECT_EQ(closedSurfaceWinding(Mesh{}), SurfaceWinding::Open); }

}  // namespace
}  // namespace marble
