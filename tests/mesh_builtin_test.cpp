// Built-in meshes: closed, outward, normalized, sane normals; names.
#include "fixtures/mesh/mesh_test_support.h"

namespace marble {
namespace {

using meshtest::bounds;
using ::testing::HasSubstr;

TEST(MeshBuiltin, NamesIncludeTheDefault) {
  auto names = builtinMeshNames();
  EXPECT_NE(std::find(names.begin(), names.end(), std::string(kDefaultBuiltinMesh)), names.end());
  for (const char* n : {"sculpture", "sphere", "cube", "slab", "torus"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
}

TEST(MeshBuiltin, UnknownName) {
  try {
    builtinMesh("dragon");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "builtin:dragon: unknown built-in mesh; known: sculpture, sphere, cube, slab, torus");
  }
}

class MeshBuiltinEach : public ::testing::TestWithParam<std::string> {};

TEST_P(MeshBuiltinEach, ClosedOutwardNormalizedWithSaneNormals) {
  const Mesh m = builtinMesh(GetParam());
  meshtest::expectWellFormed(m);
  EXPECT_TRUE(meshtest::closedAndConsistent(m));
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_LE(m.triangleCount(), 40000u);
  // Every vertex normal agrees with the faces around it (so, with positive volume, points out).
  std::vector<glm::vec3> faceSum(m.positions.size(), glm::vec3(0));
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3& a = m.positions[m.indices[t]];
    const glm::vec3 n = glm::normalize(glm::cross(m.positions[m.indices[t + 1]] - a, m.positions[m.indices[t + 2]] - a));
    for (int k = 0; k < 3; ++k) faceSum[m.indices[t + k]] += n;
  }
  for (size_t i = 0; i < m.positions.size(); ++i)
    ASSERT_GT(glm::dot(m.normals[i], glm::normalize(faceSum[i])), 0.5f) << GetParam() << " vertex " << i;
}

INSTANTIATE_TEST_SUITE_P(Mesh, MeshBuiltinEach, ::testing::ValuesIn(builtinMeshNames()));

TEST(MeshBuiltin, CubeIsFlatWith24Vertices) {
  Mesh m = builtinMesh("cube");
  EXPECT_EQ(m.positions.size(), 24u);
  EXPECT_EQ(m.triangleCount(), 12u);
  EXPECT_NEAR(signedVolume(m), 8.0, 1e-5);
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 n = m.normals[i];
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(n, m.positions[i]), 1.0f, 1e-6f);  // on the face the normal names
  }
}

TEST(MeshBuiltin, SphereIsRoundAndModest) {
  Mesh m = builtinMesh("sphere");
  EXPECT_GE(m.triangleCount(), 4000u);
  EXPECT_LE(m.triangleCount(), 6000u);
  for (size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(m.positions[i]), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(m.normals[i], m.positions[i]), 0.9999f);
  }
  EXPECT_NEAR(signedVolume(m), 4.0 / 3.0 * 3.14159265, 0.02);
}

TEST(MeshBuiltin, SlabGeometryIsAsDocumented) {
  // x in [-1, 1], y in [-0.75, 0.75], z in [-h(x), h(x)], h(x) = (0.55 + 0.45 x) / 2.
  Mesh m = builtinMesh("slab");
  auto b = bounds(m);
  EXPECT_NEAR(b.lo.x, -1.0f, 1e-6f);
  EXPECT_NEAR(b.hi.x, 1.0f, 1e-6f);
  EXPECT_NEAR(b.lo.y, -0.75f, 1e-6f);
  EXPECT_NEAR(b.hi.y, 0.75f, 1e-6f);
  EXPECT_NEAR(b.lo.z, -0.5f, 1e-6f);
  EXPECT_NEAR(b.hi.z, 0.5f, 1e-6f);
  for (const glm::vec3& p : m.positions) EXPECT_NEAR(std::abs(p.z), (0.55f + 0.45f * p.x) / 2.0f, 1e-6f);
  // Volume: length 2 x height 1.5 x mean thickness 0.55.
  EXPECT_NEAR(signedVolume(m), 2.0 * 1.5 * 0.55, 1e-5);
}

TEST(MeshBuiltin, SculptureHasThinAndThickParts) {
  Mesh m = builtinMesh("sculpture");
  EXPECT_GE(m.triangleCount(), 20000u);
  EXPECT_LE(m.triangleCount(), 40000u);
  // The tube's radius swings between about 0.18 and 0.50 (pre-normalization units) — a factor
  // of ~2.8 — which shows as the spread of distances from vertices to the tube's local centre.
  // Cheap proxy: the ring of vertices i*40 .. i*40+39 has a centroid; compare ring radii.
  float smallest = 1e9f, largest = 0.0f;
  for (size_t ring = 0; ring < 320; ++ring) {
    glm::vec3 c(0);
    for (size_t j = 0; j < 40; ++j) c += m.positions[ring * 40 + j];
    c /= 40.0f;
    float r = glm::length(m.positions[ring * 40] - c);
    smallest = std::min(smallest, r);
    largest = std::max(largest, r);
  }
  EXPECT_GT(largest / smallest, 2.5f);
}

TEST(MeshBuiltin, TorusLiesInXZ) {
  Mesh m = builtinMesh("torus");
  auto e = bounds(m).extent();
  EXPECT_NEAR(e.x, 2.0f, 1e-4f);
  EXPECT_NEAR(e.z, 2.0f, 1e-4f);
  EXPECT_NEAR(e.y, 2.0f * 0.8f / 2.8f, 1e-4f);
}

}  // namespace
}  // namespace marble
