// Normals, normalization, up axis, signed volume.
#include "fixtures/mesh/mesh_test_support.h"
#include "marble/mesh/vertex_normals.h"

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

TEST(MeshNormals, SphereNormalsAreRadial) {
  Mesh m = builtinMesh("sphere");
  m.normals.clear();
  computeVertexNormals(m, kDefaultCreaseAngleDeg);
  for (size_t i = 0; i < m.positions.size(); ++i) EXPECT_GT(glm::dot(m.normals[i], glm::normalize(m.positions[i])), 0.999f);
}

// Angle-weighted normals without a crease (kNoCreaseDeg): every face of a cube corner meets it at
// 90 degrees in all (one right-angled triangle, or two of 45), so the normal is exactly diagonal.
// Area weighting (the rule before) gives the face split at that corner twice the weight.
TEST(MeshNormals, SharedCubeCornersPointExactlyDiagonallyOutWithoutCrease) {
  Mesh m = sharedCube();
  EXPECT_NEAR(signedVolume(m), 1.0, 1e-9);
  computeVertexNormals(m, kNoCreaseDeg);
  ASSERT_EQ(m.normals.size(), 8u);
  for (size_t i = 0; i < 8; ++i) {
    glm::vec3 out = glm::normalize(m.positions[i] - glm::vec3(0.5f));
    EXPECT_GT(glm::dot(m.normals[i], out), 0.999999f) << i;
    EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-6f);
  }
}

// With a crease below 90 degrees each of the cube's 8 corners gets 3 normals, one per face, and
// every triangle's three vertices carry that triangle's own normal: the cube renders flat.
TEST(MeshNormals, CreaseSplitsTheCubeIntoThreeNormalsPerCorner) {
  for (float crease : {kDefaultCreaseAngleDeg, 30.0f, 89.0f}) {
    Mesh m = sharedCube();
    computeVertexNormals(m, crease);
    ASSERT_EQ(m.positions.size(), 24u) << crease;
    ASSERT_EQ(m.normals.size(), 24u);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      glm::vec3 sum(0.0f);
      int copies = 0;
      for (size_t i = 0; i < m.positions.size(); ++i)
        if (m.positions[i] == p) {
          ++copies;
          sum += glm::abs(m.normals[i]);
          EXPECT_GT(glm::dot(m.normals[i], p - glm::vec3(0.5f)), 0.0f);  // outward
        }
      EXPECT_EQ(copies, 3) << corner;
      EXPECT_NEAR(glm::distance(sum, glm::vec3(1.0f)), 0.0f, 1e-6f) << corner;  // +-x, +-y, +-z once each
    }
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
      const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
      for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(m.normals[m.indices[t + k]], face), 0.999999f) << t;
    }
    EXPECT_NEAR(signedVolume(m), 1.0, 1e-9);  // the same solid
  }
  Mesh smooth = sharedCube();  // faces 90 degrees apart stay joined under a crease above that
  computeVertexNormals(smooth, 91.0f);
  EXPECT_EQ(smooth.positions.size(), 8u);
}

// A known fan where the two rules differ: two right-angled corners at the origin, a big triangle
// facing +Z and a small one facing 45 degrees off it (sharing the edge along +Y).
TEST(MeshNormals, AngleWeightedNotAreaWeighted) {
  Mesh m;
  m.positions = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {-1, 0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  computeVertexNormals(m, kDefaultCreaseAngleDeg);
  ASSERT_EQ(m.positions.size(), 4u);  // 45 degrees: a smooth edge
  const glm::vec3 angle = glm::normalize(glm::vec3(0, 0, 1) * 1.5707964f + glm::normalize(glm::vec3(1, 0, 1)) * 1.5707964f);
  EXPECT_NEAR(glm::dot(m.normals[0], angle), 1.0f, 1e-6f);  // 22.5 degrees from +Z
  // Negative control: area weighting (cross products (0,0,100) and (10,0,10)) leans 5.2 degrees.
  const glm::vec3 area = glm::normalize(glm::vec3(10, 0, 110));
  EXPECT_LT(glm::dot(m.normals[0], area), std::cos(glm::radians(15.0f)));
  // Vertex 1 belongs to the big triangle only, 3 to the small one only.
  EXPECT_NEAR(glm::dot(m.normals[1], glm::vec3(0, 0, 1)), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(m.normals[3], glm::normalize(glm::vec3(1, 0, 1))), 1.0f, 1e-6f);
}

// Vertices at the same position are one point: triangles that do not share vertex indices (STL,
// seams of texture coordinates) are still smooth across their common edge.
TEST(MeshNormals, SamePositionIsOnePoint) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0.2f}, {0, 1, 0}};
  m.texcoords = {{0, 0}, {1, 0}, {0, 1}, {0.5f, 0}, {1, 1}, {0, 0.5f}};
  m.indices = {0, 1, 2, 3, 4, 5};
  computeVertexNormals(m, kDefaultCreaseAngleDeg);
  ASSERT_EQ(m.positions.size(), 6u);
  EXPECT_NEAR(glm::distance(m.normals[1], m.normals[3]), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(m.normals[2], m.normals[5]), 0.0f, 1e-6f);
  EXPECT_LT(glm::dot(m.normals[1], glm::vec3(0, 0, 1)), 0.9999f);  // blended with the tilted one
}

// Blender's other hard edges: an edge of three triangles, and one whose two triangles are wound
// against each other, are hard whatever the angle; a split vertex keeps its texture coordinate.
TEST(MeshNormals, NonManifoldAndFlippedEdgesAreHard) {
  {
    Mesh m;  // a flat square whose halves are wound against each other
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 1, 2, 0, 3, 2};
    computeVertexNormals(m, kDefaultCreaseAngleDeg);
    ASSERT_EQ(m.positions.size(), 6u);  // 0 and 2 split
    ASSERT_EQ(m.texcoords.size(), 6u);
    EXPECT_EQ(m.texcoords[4], m.texcoords[m.indices[3] == 4 ? 0 : 2]);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(m.normals[m.indices[k]].z, 1.0f, 1e-6f);
    for (int k = 3; k < 6; ++k) EXPECT_NEAR(m.normals[m.indices[k]].z, -1.0f, 1e-6f);
  }
  {
    Mesh m;  // three fins on one edge (0-1), nearly coplanar pairs
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0.01f}, {0.5f, -1, -0.01f}};
    m.indices = {0, 1, 2, 1, 0, 3, 1, 0, 4};
    computeVertexNormals(m, kDefaultCreaseAngleDeg);
    EXPECT_EQ(m.positions.size(), 9u);  // 0 and 1 in three fans each
  }
}

TEST(MeshNormals, DegenerateAndIsolatedVerticesGetUpNotNaN) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}, {1, 1, 1}};
  m.indices = {0, 1, 2, 4, 4, 4};  // collinear, then all-one-point
  computeVertexNormals(m, kDefaultCreaseAngleDeg);
  ASSERT_EQ(m.normals.size(), 5u);
  for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

TEST(MeshNormals, DegenerateTrianglesDoNotDisturbNeighbours) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5f, 0, 0}};
  m.indices = {0, 1, 2, 0, 3, 1};  // the second is flat along the x axis
  for (float crease : {kDefaultCreaseAngleDeg, kNoCreaseDeg}) {
    computeVertexNormals(m, crease);
    ASSERT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
    EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));
  }
}

TEST(MeshNormals, InwardWindingGivesInwardNormals) {
  // Documented behaviour: winding is trusted, never guessed (the Utah teapot file is wound inward).
  Mesh m = sharedCube();
  for (size_t t = 0; t < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
  EXPECT_LT(signedVolume(m), 0.0);
  computeVertexNormals(m, kNoCreaseDeg);
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
