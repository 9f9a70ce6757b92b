// OBJ loading: statement forms, index forms, vertex splitting, fans, errors with line numbers.
#include "fixtures/mesh/mesh_test_support.h"
#include "marble/scene/scene.h"

namespace marble {
namespace {

// Loader tests check structure (welding, indices) on smooth shapes: normals without a crease
// (kNoCreaseDeg); the crease itself is tested in mesh_geometry_test.cpp.

using meshtest::bounds;
using meshtest::fixture;
using meshtest::loadError;
using meshtest::TempDir;
using ::testing::HasSubstr;

TEST(MeshObj, FlatCubeSplitsVerticesByNormal) {
  Mesh m = loadMesh(fixture("cube_flat.obj"));
  meshtest::expectWellFormed(m);
  EXPECT_EQ(m.positions.size(), 24u);  // 8 positions x 3 face normals each
  EXPECT_EQ(m.triangleCount(), 12u);
  EXPECT_TRUE(m.texcoords.empty());
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_TRUE(meshtest::closedAndConsistent(m));
  // File normals are kept: each one is axis-aligned and points away from the centre.
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 n = m.normals[i];
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, 1e-6f);
    EXPECT_GT(glm::dot(n, m.positions[i]), 0.0f);
  }
}

// The shared cube.obj's form (8 shared corners, no normals): the default crease splits it into
// 24 vertices with flat faces; a scene's crease_angle_deg of 180 keeps it one smooth blob.
TEST(MeshObj, CreaseAngleFromTheSceneSplitsASharedCube) {
  TempDir dir;
  const auto obj = dir.write("cube.obj",
                             "v 0 0 0\nv 0 0 1\nv 0 1 0\nv 0 1 1\nv 1 0 0\nv 1 0 1\nv 1 1 0\nv 1 1 1\n"
                             "f 1 7 5\nf 1 3 7\nf 1 4 3\nf 1 2 4\nf 3 8 7\nf 3 4 8\nf 5 7 8\nf 5 8 6\n"
                             "f 1 5 6\nf 1 6 2\nf 2 6 8\nf 2 8 4\n");
  Mesh flat = loadMesh(obj);
  EXPECT_EQ(flat.positions.size(), 24u);
  for (const glm::vec3& n : flat.normals) EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, 1e-6f);
  std::vector<std::string> warnings;
  const auto scene = dir.write("scene.json", "{\"mesh\": \"cube.obj\", \"crease_angle_deg\": 180}");
  Scene s = loadScene(scene, warnings);
  EXPECT_EQ(s.crease_angle_deg, 180.0f);
  EXPECT_EQ(loadSceneMesh(s).positions.size(), 8u);
  const auto bad = dir.write("bad.json", "{\"crease_angle_deg\": 200}");
  try {
    loadScene(bad, warnings);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("crease_angle_deg"), std::string::npos) << e.what();
  }
}

TEST(MeshObj, TexturedQuadIgnoresOtherStatementsAndFans) {
  Mesh m = loadMesh(fixture("quad_textured.obj"));
  meshtest::expectWellFormed(m);
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.triangleCount(), 2u);
  ASSERT_EQ(m.texcoords.size(), 4u);
  // Vertex 3 of the file (20, 30) had texture coordinate (1, 1): after normalization (1, 1, 0).
  bool found = false;
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(m.normals[i].z, 1.0f, 1e-6f);
    if (glm::length(m.positions[i] - glm::vec3(1, 1, 0)) < 1e-5f) {
      found = true;
      EXPECT_EQ(m.texcoords[i], glm::vec2(1, 1));
    }
  }
  EXPECT_TRUE(found);
  auto b = bounds(m);
  EXPECT_NEAR(b.extent().z, 0.0f, 1e-6f);
}

TEST(MeshObj, AllCornerForms) {
  TempDir dir;
  auto p = dir.write("forms.obj",
                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                     "vt 0 0\nvt 1 0\nvt 0 1\n"
                     "vn 0 0 1\n"
                     "f 1/1/1 3/3/1 2/2/1\n"   // v/vt/vn
                     "f 1/1 2/2 4/1\n"         // v/vt (no normal: normals dropped for all)
                     "f 1//1 4//1 3//1\n"      // v//vn (no vt: texcoords dropped for all)
                     "f 2 3 4\n");             // v
  Mesh m = loadMesh(p, meshtest::noCrease());
  meshtest::expectWellFormed(m);
  EXPECT_EQ(m.triangleCount(), 4u);
  EXPECT_EQ(m.positions.size(), 4u);  // neither vt nor vn is used everywhere: the plain fast path
  EXPECT_TRUE(m.texcoords.empty());
  EXPECT_GT(signedVolume(m), 0.0);
}

TEST(MeshObj, NegativeIndices) {
  TempDir dir;
  // Relative indices count back from the vertices defined so far, so the same "-3 -2 -1"
  // means different vertices in the two places.
  auto p = dir.write("relative.obj",
                     "v 0 0 0\nv 0 1 0\nv 1 0 0\n"
                     "f -3 -2 -1\n"  // 1 2 3
                     "v 0 0 1\n"
                     "f -4 -1 -3\n"  // 1 4 2
                     "f -4 -2 -1\n"  // 1 3 4
                     "f -2 -3 -1\n"  // 3 2 4
                     "f -1/-1 -2/-1 -3/-1\n"
                     "vt 0 0\n");
  // The last face uses vt -1 before any vt exists: an error on that line.
  EXPECT_THAT(loadError(p), HasSubstr("relative.obj: line 9: relative texture coordinate index -1 is out of range"));

  auto q = dir.write("relative_ok.obj",
                     "v 0 0 0\nv 0 1 0\nv 1 0 0\n"
                     "f -3 -2 -1\n"
                     "v 0 0 1\n"
                     "f -4 -1 -3\n"
                     "f -4 -2 -1\n"
                     "f -2 -3 -1\n");
  Mesh m = loadMesh(q, meshtest::noCrease());
  ASSERT_EQ(m.indices.size(), 12u);
  EXPECT_EQ(std::vector<uint32_t>(m.indices.begin(), m.indices.end()),
            (std::vector<uint32_t>{0, 1, 2, 0, 3, 1, 0, 2, 3, 2, 1, 3}));
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_TRUE(meshtest::closedAndConsistent(m));
}

TEST(MeshObj, PolygonIsFanned) {
  TempDir dir;
  auto p = dir.write("hexagon.obj",
                     "v 1 0 0\nv 0.5 0.866 0\nv -0.5 0.866 0\nv -1 0 0\nv -0.5 -0.866 0\nv 0.5 -0.866 0\n"
                     "f 1 2 3 4 5 6\n");
  Mesh m = loadMesh(p);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5}));
  for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-5f);
}

TEST(MeshObj, SharedPositionsWithDifferentTexcoordsSplit) {
  TempDir dir;
  // Two triangles share the edge 1-3 in position but not in texture coordinate.
  auto p = dir.write("seam.obj",
                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                     "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                     "f 1/1 2/2 3/3\n"
                     "f 1/5 3/4 4/4\n");
  Mesh m = loadMesh(p);
  EXPECT_EQ(m.positions.size(), 6u);  // 1/1, 2/2, 3/3, 1/5, 3/4, 4/4: six distinct pairs
  EXPECT_EQ(m.triangleCount(), 2u);
  ASSERT_EQ(m.texcoords.size(), m.positions.size());
}

TEST(MeshObj, CrlfTabsCommentsAndBom) {
  TempDir dir;
  auto p = dir.write("crlf.obj",
                     "\xEF\xBB\xBF# exported on Windows\r\n"
                     "v\t0 0 0 # trailing comment\r\n"
                     "v 1 0 0\r\n"
                     "  v 0 1 0\r\n"
                     "v +0 -0 1e0\r\n"
                     "\r\n"
                     "f 1 3 2\r\nf 1 2 4\r\nf 1 4 3\r\nf\t2 3 4 \r\n");
  Mesh m = loadMesh(p);
  meshtest::expectWellFormed(m);
  EXPECT_EQ(m.triangleCount(), 4u);
  EXPECT_GT(signedVolume(m), 0.0);
}

TEST(MeshObj, ForwardReferenceIsAllowedWhenResolvedByTheEnd) {
  TempDir dir;
  auto p = dir.write("forward.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(loadMesh(p).triangleCount(), 1u);
}

TEST(MeshObj, ZeroIndexIsAnError) {
  TempDir dir;
  auto p = dir.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 0 1 2\n");
  EXPECT_THAT(loadError(p), HasSubstr("zero.obj: line 5: vertex index 0 is invalid (OBJ indices start at 1)"));
}

TEST(MeshObj, OutOfRangeIndexNamesTheLine) {
  TempDir dir;
  auto p = dir.write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 7\n");
  EXPECT_THAT(loadError(p), HasSubstr("range.obj: line 5: vertex index 7 is out of range (the file has 3 vertices)"));
  auto q = dir.write("neg_range.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\n");
  EXPECT_THAT(loadError(q), HasSubstr("neg_range.obj: line 3: relative vertex index -3 is out of range"));
  auto r = dir.write("vn_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n");
  EXPECT_THAT(loadError(r), HasSubstr("vn_range.obj: line 5: normal index 2 is out of range"));
}

TEST(MeshObj, NonFiniteCoordinateIsAnError) {
  TempDir dir;
  auto p = dir.write("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_THAT(loadError(p), HasSubstr("nan.obj: line 2: 'v': number is NaN or infinite"));
  auto q = dir.write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 inf\nf 1 2 3\n");
  EXPECT_THAT(loadError(q), HasSubstr("inf.obj: line 3:"));
  auto r = dir.write("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 1e60\nf 1 2 3\n");
  EXPECT_THAT(loadError(r), HasSubstr("huge.obj: line 3: 'v': number is NaN or infinite"));
}

TEST(MeshObj, MalformedStatements) {
  TempDir dir;
  EXPECT_THAT(loadError(dir.write("short_v.obj", "v 0 0\nf 1 1 1\n")), HasSubstr("short_v.obj: line 1: 'v' needs 3 numbers"));
  EXPECT_THAT(loadError(dir.write("word.obj", "v 0 zero 0\n")),
              HasSubstr("word.obj: line 1: 'v': expected a number, found 'zero'"));
  EXPECT_THAT(loadError(dir.write("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n")),
              HasSubstr("two.obj: line 3: face has 2 vertices; a face needs at least 3"));
  EXPECT_THAT(loadError(dir.write("badf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x3\n")),
              HasSubstr("badf.obj: line 4: bad face vertex 'x3'"));
}

TEST(MeshObj, OnlyVerticesIsNoFaces) {
  TempDir dir;
  auto p = dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n");
  EXPECT_THAT(loadError(p), HasSubstr("points.obj: no triangles: the file has 3 vertices but no faces"));
}

}  // namespace
}  // namespace marble
