// Normals, normalization, up axis, signed volume.
#include "fixtures/mesh/mesh_test_support.h"

namespace marble {
namespace {

using meshtest::bounds;
using meshtest::TempDir;
using ::testing::HasSubstr;

// An 8-vertex cube (shared corners), [0,1]^3, wound outward.
Mesh sharedCube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  m.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  return m;
}

TEST(MeshNormals, SharedCubeCornersPointDiagonallyOut) {
  Mesh m = sharedCube();
  EXPECT_NEAR(signedVolume(m), 1.0, 1e-9);
  computeSmoothNormals(m);
  ASSERT_EQ(m.normals.size(), 8u);
  for (size_t i = 0; i < 8; ++i) {
    glm::vec3 out = glm::normalize(m.positions[i] - glm::vec3(0.5f));
    // Area-weighted over two triangles of one face and one of each other face, or one and two:
    // not exactly diagonal, but well within 20 degrees of it.
    EXPECT_GT(glm::dot(m.normals[i], out), 0.94f) << i;
    EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-6f);
  }
}

TEST(MeshNormals, SphereNormalsAreRadial) {
  Mesh m = builtinMesh("sphere");
  m.normals.clear();
  computeSmoothNormals(m);
  for (size_t i = 0; i < m.positions.size(); ++i) EXPECT_GT(glm::dot(m.normals[i], glm::normalize(m.positions[i])), 0.999f);
}

TEST(MeshNormals, AreaWeighted) {
  // A vertex shared by a big triangle facing +Z and a small one facing +X: the normal leans to +Z.
  Mesh m;
  m.positions = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 1, 0}, {0, 0, -1}};
  m.indices = {0, 1, 2, 0, 3, 4};
  computeSmoothNormals(m);
  glm::vec3 expected = glm::normalize(glm::vec3(-1, 0, 100));  // cross products: (0,0,100) and (-1,0,0)
  EXPECT_NEAR(glm::dot(m.normals[0], expected), 1.0f, 1e-6f);
}

TEST(MeshNormals, DegenerateAndIsolatedVerticesGetUpNotNaN) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}, {1, 1, 1}};
  m.indices = {0, 1, 2, 4, 4, 4};  // collinear, then all-one-point
  computeSmoothNormals(m);
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

TEST(MeshNormals, DegenerateTrianglesDoNotDisturbNeighbours) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5f, 0, 0}};
  m.indices = {0, 1, 2, 0, 3, 1};  // the second is flat along the x axis
  computeSmoothNormals(m);
  EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));
}

TEST(MeshNormals, InwardWindingGivesInwardNormals) {
  // Documented behaviour: winding is trusted, never guessed (the Utah teapot file is wound inward).
  Mesh m = sharedCube();
  for (size_t t = 0; t < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
  EXPECT_LT(signedVolume(m), 0.0);
  computeSmoothNormals(m);
  EXPECT_LT(glm::dot(m.normals[7], glm::vec3(1)), 0.0f);
}

TEST(MeshNormalize, CentresAndScalesLargestExtentToTwo) {
  Mesh m;
  m.positions = {{10, 20, 30}, {14, 21, 30.5f}, {12, 20, 31}};
  m.indices = {0, 1, 2};
  normalizeMesh(m);
  auto b = bounds(m);
  EXPECT_NEAR(b.extent().x, 2.0f, 1e-6f);
  EXPECT_NEAR(b.extent().y, 0.5f, 1e-6f);
  EXPECT_NEAR(b.extent().z, 0.5f, 1e-6f);
  EXPECT_NEAR(b.centre().x, 0.0f, 1e-6f);
  EXPECT_NEAR(b.centre().y, 0.0f, 1e-6f);
  EXPECT_NEAR(b.centre().z, 0.0f, 1e-6f);
}

TEST(MeshNormalize, HugeAndTinyCoordinates) {
  Mesh big;
  big.positions = {{-3e38f, 0, 0}, {3e38f, 1e38f, 0}, {0, 0, 3e38f}};
  big.indices = {0, 1, 2};
  normalizeMesh(big);
  EXPECT_NEAR(bounds(big).extent().x, 2.0f, 1e-6f);
  Mesh tiny;
  tiny.positions = {{0, 0, 0}, {1e-30f, 0, 0}, {0, 1e-30f, 0}};
  tiny.indices = {0, 1, 2};
  normalizeMesh(tiny);
  EXPECT_NEAR(bounds(tiny).extent().y, 2.0f, 1e-6f);
}

TEST(MeshNormalize, ZeroExtentThrowsWithBoundsPlace) {
  Mesh m;
  m.positions = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  m.indices = {0, 1, 2};
  try {
    normalizeMesh(m, "thing.obj");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "thing.obj: bounds: all vertices are at the same point (zero extent); cannot normalize");
  }
  Mesh empty;
  EXPECT_THROW(normalizeMesh(empty), InputError);
  for (const glm::vec3& p : m.positions) EXPECT_TRUE(std::isfinite(p.x));
}

TEST(MeshUpAxis, ParseAndName) {
  EXPECT_EQ(parseUpAxis("y"), UpAxis::Y);
  EXPECT_EQ(parseUpAxis("+Y"), UpAxis::Y);
  EXPECT_EQ(parseUpAxis("Z"), UpAxis::Z);
  EXPECT_EQ(parseUpAxis("+z"), UpAxis::Z);
  EXPECT_EQ(parseUpAxis("x"), UpAxis::X);
  EXPECT_EQ(parseUpAxis("-y"), UpAxis::NegY);
  EXPECT_EQ(parseUpAxis("-Z"), UpAxis::NegZ);
  EXPECT_EQ(parseUpAxis(" -x "), UpAxis::NegX);
  EXPECT_THROW(parseUpAxis("w"), std::invalid_argument);
  EXPECT_THROW(parseUpAxis(""), std::invalid_argument);
  EXPECT_THROW(parseUpAxis("--y"), std::invalid_argument);
  for (UpAxis a : {UpAxis::Y, UpAxis::Z, UpAxis::X, UpAxis::NegY, UpAxis::NegZ, UpAxis::NegX})
    EXPECT_EQ(parseUpAxis(upAxisName(a)), a);
}

TEST(MeshUpAxis, NamedAxisBecomesPlusYByAProperRotation) {
  const std::pair<UpAxis, glm::vec3> cases[] = {
      {UpAxis::Y, {0, 1, 0}},     {UpAxis::Z, {0, 0, 1}},     {UpAxis::X, {1, 0, 0}},
      {UpAxis::NegY, {0, -1, 0}}, {UpAxis::NegZ, {0, 0, -1}}, {UpAxis::NegX, {-1, 0, 0}},
  };
  for (const auto& [axis, fileUp] : cases) {
    Mesh m;
    m.positions = {fileUp, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.normals = {fileUp, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    applyUpAxis(m, axis);
    EXPECT_EQ(m.positions[0], glm::vec3(0, 1, 0)) << upAxisName(axis);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 1, 0)) << upAxisName(axis);
    // Images of the basis form a right-handed frame: det = +1.
    glm::mat3 r(m.positions[1], m.positions[2], m.positions[3]);
    EXPECT_FLOAT_EQ(glm::determinant(r), 1.0f) << upAxisName(axis);
  }
  // The brief's example: Z-up maps (x, y, z) to (x, z, -y).
  Mesh m;
  m.positions = {{1, 2, 3}};
  applyUpAxis(m, UpAxis::Z);
  EXPECT_EQ(m.positions[0], glm::vec3(1, 3, -2));
}

TEST(MeshUpAxis, LoadMeshAppliesItAndKeepsVolumePositive) {
  TempDir dir;
  // A tall box along +Z: loaded Z-up it becomes tall along +Y.
  auto p = dir.write("tall.obj",
                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 4\nv 1 0 4\nv 1 1 4\nv 0 1 4\n"
                     "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 1 2 6 5\nf 4 8 7 3\n");
  Mesh y = loadMesh(p);
  Mesh z = loadMesh(p, UpAxis::Z);
  EXPECT_NEAR(bounds(y).extent().z, 2.0f, 1e-6f);
  EXPECT_NEAR(bounds(z).extent().y, 2.0f, 1e-6f);
  EXPECT_NEAR(bounds(z).extent().z, 0.5f, 1e-6f);
  EXPECT_GT(signedVolume(z), 0.0);
  EXPECT_NEAR(signedVolume(z), signedVolume(y), 1e-6);
}

}  // namespace
}  // namespace marble
